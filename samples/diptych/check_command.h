#pragma once
#include <CLI/CLI.hpp>

namespace diptych::cli {
// `diptych check SCENE [options]`: the numerics suite (docs/numerics.md). Renders the scene as
// given and scaled, translated and seen at grazing incidence, with the exact and raster recipes,
// and reports per case the FLIP error against the untransformed render, NaN/Inf counts,
// self-intersections and lost shadows of the secondary rays, and shadow-map depth warnings.
void addCheckCommand(CLI::App& app, int& exitCode);
}  // namespace diptych::cli
