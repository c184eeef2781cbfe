#pragma once
// The reference's per-pixel sphere-tracing steps in a comparison (passes/rt/sdf_steps.h): a heat
// map and the frame's figures in results.json, where the scene has SDF objects.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/image.h"

namespace diptych::cli {

// Writes images/reference-sdf-steps.exr (all four channels) and heatmaps/reference-sdf-steps.png
// (steps per pixel, viridis from 0 to the 99th percentile of the pixels with steps), appends them
// to `written` and returns results.json's "sdf_steps" entry: rays, steps, mean and max steps per
// ray, misses by the iteration cap, the largest pixel, the files and the method.
nlohmann::json writeSdfStepReport(const std::filesystem::path& dir, const Image& steps,
                                  std::vector<std::string>& written);

// The report.html section for that entry ("" when the entry is null).
std::string sdfStepSection(const nlohmann::json& entry);

}  // namespace diptych::cli
