#pragma once
#include <CLI/CLI.hpp>

namespace diptych::cli {
// `diptych passes [--markdown]`: the technique slots, their producers and every pass type with
// its parameters, printed from the registry (passes/registry.cpp, passes/slots.cpp).
// --markdown prints the tables of docs/technique-slots.md.
void addPassesCommand(CLI::App& app, int& exitCode);
}  // namespace diptych::cli
