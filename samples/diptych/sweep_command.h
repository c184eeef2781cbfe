#pragma once
#include <CLI/CLI.hpp>

namespace diptych::cli {
// `diptych sweep SCENE --slot SLOT=TYPE[:k=v,...] --vary KEY=VALUES ... [--vary-light ...]`
// (docs/sweep.md) and `diptych shadow-bias [SCENE]` on top of it (docs/shadow-bias.md).
void addSweepCommand(CLI::App& app, int& exitCode);
void addShadowBiasCommand(CLI::App& app, int& exitCode);
}  // namespace diptych::cli
