#pragma once
#include <CLI/CLI.hpp>

namespace diptych::cli {
// `diptych diff IMAGE REFERENCE [options]`: image error metrics (docs/metrics.md) as a table or
// JSON, an optional heat map, and thresholds for scripts. Exit status: 0 normally, 1 when a
// --fail-above/--fail-below threshold is crossed or an input is bad, 2 for usage errors.
void addDiffCommand(CLI::App& app, int& exitCode);
}  // namespace diptych::cli
