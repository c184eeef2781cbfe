#pragma once
#include <CLI/CLI.hpp>

namespace diptych::cli {
// `diptych render SCENE [options]`: compiles a recipe for the scene, runs it for warm-up and
// measured frames, writes the output image, graph and timings, and prints a per-pass table.
void addRenderCommand(CLI::App& app, int& exitCode);
}  // namespace diptych::cli
