#pragma once
#include <CLI/CLI.hpp>

namespace diptych::cli {
// `diptych view SCENE [options]`: an interactive window (GLFW + Dear ImGui) over the same frame
// graph, recipes and metrics as render and compare (docs/viewer.md).
void addViewCommand(CLI::App& app, int& exitCode);
}  // namespace diptych::cli
