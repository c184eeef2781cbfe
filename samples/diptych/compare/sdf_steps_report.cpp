#include "samples/diptych/compare/sdf_steps_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "engine/metrics/metrics.h"
#include "passes/rt/sdf_steps.h"
#include "samples/diptych/compare/report.h"

namespace diptych::cli {
namespace {

// The heat map's top: the 99th percentile of the pixels with any steps, so that the few
// silhouette pixels that creep along the surface up to the cap (hundreds of steps against a
// mean near ten) saturate instead of darkening everything else.
float heatTop(const Image& steps) {
  std::vector<float> v;
  for (int y = 0; y < steps.height; ++y)
    for (int x = 0; x < steps.width; ++x)
      if (steps.at(x, y, 0) > 0.f) v.push_back(steps.at(x, y, 0));
  if (v.empty()) return 1.f;
  const auto k = v.begin() + std::ptrdiff_t(0.99 * double(v.size() - 1));
  std::nth_element(v.begin(), k, v.end());
  return std::max(*k, 1.f);
}

}  // namespace

nlohmann::json writeSdfStepReport(const std::filesystem::path& dir, const Image& steps,
                                  std::vector<std::string>& written) {
  const SdfStepSummary s = summariseSdfSteps(steps);
  const std::string exr = "images/reference-sdf-steps.exr",
                    png = "heatmaps/reference-sdf-steps.png";
  writeImage(dir / exr, steps);
  const float top = heatTop(steps);
  writeImage(dir / png, heatMap(steps, top));
  written.push_back(exr);
  written.push_back(png);
  return {{"rays", s.rays},
          {"steps", s.steps},
          {"mean_steps_per_ray", s.meanSteps()},
          {"max_steps_per_ray", s.maxSteps},
          {"capped_misses", s.capped},
          {"max_steps_per_pixel", s.maxPixelSteps},
          {"heatmap_top", top},
          {"files", {{"exr", exr}, {"heatmap", png}}},
          {"method",
           "the reference's last frame; per pixel, every ray of its ray tree (shadow rays too) "
           "that reached an SDF object's box: R steps summed, G rays, B the most steps of one "
           "ray, A misses by the iteration cap; the heat map shows R (viridis) from 0 to "
           "heatmap_top, the "
           "99th percentile of the pixels with steps, saturating above"}};
}

std::string sdfStepSection(const nlohmann::json& e) {
  if (e.is_null()) return "";
  return fmt::format(
      "<h2>Sphere-tracing steps (reference)</h2>\n<p id=\"sdf-steps\">{:.0f} rays reached an SDF "
      "object: mean {:.2f} steps per ray, max {:.0f}, {:.0f} misses by the iteration cap. "
      "Heat map: steps per pixel, 0 to {:.0f} (the largest pixel: {:.0f}).</p>\n<img src=\"{}\" "
      "alt=\"sphere-tracing steps "
      "per pixel\">\n<p class=\"caption\">{}</p>\n",
      e["rays"].get<double>(), e["mean_steps_per_ray"].get<double>(),
      e["max_steps_per_ray"].get<double>(), e["capped_misses"].get<double>(),
      e["heatmap_top"].get<double>(), e["max_steps_per_pixel"].get<double>(),
      e["files"]["heatmap"].get<std::string>(), htmlEscape(e["method"].get<std::string>()));
}

}  // namespace diptych::cli
