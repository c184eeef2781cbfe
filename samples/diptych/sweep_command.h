#pragma once
#include <CLI/CLI.hpp>

namespace diptych::cli {
// `diptych sweep SCENE --slot SLOT=TYPE[:k=v,...] --vary KEY=VALUES ... [--vary-light ...]`
// (docs/sweep.md) and `diptych shadow-bias [SCENE]` on top of it (docs/shadow-bias.md).
void addSweepCommand(CLI::App& app, int& exitCode);
void addShadowBiasCommand(CLI::App& app, int& exitCode);
// WIDTHxHEIGHT with each in 1..8192, or InputError naming `option`.
void parseSize(const std::string& option, const std::string& text, int& width, int& height);
}  // namespace diptych::cli
