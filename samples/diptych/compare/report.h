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

// The summary table on stdout: a same-frame variant as "same frame as NAME (reason)", with
// rounds each speed-up's range over the rounds beside it, with one round a note that such
// speed-ups do not separate small differences from load noise.
void printSummaryTable(const std::vector<ReportVariant>& variants, const std::string& metric,
                       int rounds);

// Shared by every report page: HTML escaping and the style sheet.
std::string htmlEscape(const std::string& s);
const char* reportStyle();

}  // namespace diptych::cli
