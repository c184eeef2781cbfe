#pragma once
// Files a comparison writes: images (EXR + PNG), heat maps, side-by-side panels, graphs,
// results.json / results.csv, the error-versus-time plot (matplotlib) and report.html.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/image.h"

namespace diptych::cli {

struct ReportVariant {
  std::string name;
  Image image, heatmap;
  std::string dot;        // the compiled graph with its timings, Graphviz DOT
  nlohmann::json result;  // the variant's entry of results.json (metrics, timings, signals...)
};

// Writes every file under `dir` and returns the paths written (relative to dir).
std::vector<std::string> writeReport(const std::filesystem::path& dir, const nlohmann::json& header,
                                     const Image& reference, std::vector<ReportVariant>& variants,
                                     const std::string& plotMetric);

// Shared by every report page: HTML escaping and the style sheet.
std::string htmlEscape(const std::string& s);
const char* reportStyle();

}  // namespace diptych::cli
