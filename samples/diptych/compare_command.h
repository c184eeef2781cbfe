#pragma once
#include <CLI/CLI.hpp>

namespace diptych::cli {
// `diptych compare [SCENE] [--variants FILE|names] [--reference whitted|distributed:SPP|path:SPP]
//  [--frames N] [--out DIR]`: every variant against one reference, measured (docs/compare.md).
void addCompareCommand(CLI::App& app, int& exitCode);
}  // namespace diptych::cli
