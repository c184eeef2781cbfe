#pragma once
// Files of a shadow-bias study: summary.json / summary.csv (one row per curve), the plots
// (plot_shadow_bias.py, matplotlib) and report.html.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace diptych::cli {

std::vector<std::string> writeBiasReport(const std::filesystem::path& dir,
                                         const nlohmann::json& summary);

}  // namespace diptych::cli
