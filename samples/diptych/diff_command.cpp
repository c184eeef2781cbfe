#include "samples/diptych/diff_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "engine/core/error.h"
#include "engine/core/known.h"
#include "engine/core/output_file.h"
#include "engine/metrics/metrics.h"

namespace diptych::cli {
namespace {

struct DiffOptions {
  std::string image, reference, metrics, heatmap, heatmapMetric = "flip";
  std::vector<std::string> failAbove, failBelow;
  double heatmapMax = 0, psnrPeak = 0, ssimDataRange = 0, ppd = 67.0, relMseEpsilon = 1e-2;
  bool json = false;
};

// Keys that state a parameter a metric used rather than an error measure.
bool isParameter(const std::string& key) {
  return key == "psnr_peak" || key == "ssim_data_range" || key == "flip_variant" ||
         key == "flip_pixels_per_degree" || key.rfind("flip_exposure_", 0) == 0;
}

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

// The scalar names a threshold may name, and the group that computes each.
std::string groupOf(const std::string& metric) {
  if (metric.rfind("flip_", 0) == 0) return "flip";
  return metric;
}
const std::vector<std::string>& thresholdNames() {
  static const std::vector<std::string> names{
      "mse", "rmse", "relmse", "psnr", "ssim", "flip_mean", "flip_p50", "flip_p95", "flip_p99"};
  return names;
}

struct Threshold {
  std::string metric;
  double value = 0;
  bool above = true;
};

Threshold parseThreshold(const std::string& text, bool above) {
  const auto eq = text.find('=');
  Threshold t{text.substr(0, eq), 0, above};
  const std::string option = above ? "--fail-above" : "--fail-below";
  if (eq == std::string::npos)
    throw CLI::ValidationError(option, "expected METRIC=VALUE, got '" + text + "'");
  if (std::find(thresholdNames().begin(), thresholdNames().end(), t.metric) ==
      thresholdNames().end())
    throw CLI::ValidationError(option, unknownName("metric", t.metric, thresholdNames()));
  const std::string number = text.substr(eq + 1);
  char* end = nullptr;
  t.value = std::strtod(number.c_str(), &end);
  if (number.empty() || *end != '\0' || !std::isfinite(t.value))
    throw CLI::ValidationError(option, "'" + number + "' is not a finite number");
  return t;
}

// CLI::PositiveNumber lets NaN and Inf through and prints its bound, not the value, on error.
std::string finitePositive(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v) || !(v > 0))
    return "'" + text + "' is not a finite positive number";
  return {};
}

std::string formatValue(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return fmt::format("{:.6g}", v);
}

int runDiff(const DiffOptions& o) {
  std::vector<Threshold> thresholds;
  for (const std::string& t : o.failAbove) thresholds.push_back(parseThreshold(t, true));
  for (const std::string& t : o.failBelow) thresholds.push_back(parseThreshold(t, false));

  MetricOptions options;
  options.psnrPeak = o.psnrPeak;
  options.ssimDataRange = o.ssimDataRange;
  options.flipPixelsPerDegree = o.ppd;
  options.relMseEpsilon = o.relMseEpsilon;
  options.testName = o.image;
  options.referenceName = o.reference;
  options.metrics = splitList(o.metrics);
  // A threshold's metric is computed even when --metrics leaves it out.
  if (!options.metrics.empty())
    for (const Threshold& t : thresholds)
      if (std::find(options.metrics.begin(), options.metrics.end(), groupOf(t.metric)) ==
          options.metrics.end())
        options.metrics.push_back(groupOf(t.metric));

  if (!o.heatmap.empty()) checkOutputPath("--heatmap", o.heatmap);
  const Image test = readLinearImage(o.image);
  const Image reference = readLinearImage(o.reference);
  const std::map<std::string, double> values = computeMetrics(test, reference, options);

  Image heat;
  float heatMax = 0;
  if (!o.heatmap.empty()) {
    const Image map = o.heatmapMetric == "mse" ? squaredErrorMap(test, reference)
                                               : flipErrorMap(test, reference, options);
    heatMax = float(o.heatmapMax);
    // FLIP is in [0, 1] by construction; squared errors are scaled to their maximum.
    if (heatMax <= 0)
      heatMax =
          o.heatmapMetric == "mse" ? *std::max_element(map.pixels.begin(), map.pixels.end()) : 1.f;
    heat = heatMap(map, heatMax);
  }

  std::vector<std::string> failures;
  for (const Threshold& t : thresholds) {
    const double v = values.at(t.metric);
    if (t.above ? v > t.value : v < t.value)
      failures.push_back(fmt::format("{} = {} is {} the threshold {}", t.metric, formatValue(v),
                                     t.above ? "above" : "below", formatValue(t.value)));
  }

  if (!o.heatmap.empty()) writeImage(o.heatmap, heat);

  if (o.json) {
    nlohmann::json j;
    j["image"] = o.image;
    j["reference"] = o.reference;
    j["width"] = test.width;
    j["height"] = test.height;
    nlohmann::json metrics = nlohmann::json::object(), params = nlohmann::json::object();
    for (const auto& [k, v] : values) {
      // JSON has no infinity: the PSNR of identical images is written as null.
      nlohmann::json value = std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
      (isParameter(k) ? params : metrics)[k] = value;
    }
    j["metrics"] = metrics;
    j["parameters"] = params;
    if (!o.heatmap.empty()) {
      j["heatmap"] = {{"file", o.heatmap}, {"metric", o.heatmapMetric}, {"max", heatMax}};
    }
    j["failed"] = failures;
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf("image      %s (%dx%d)\nreference  %s\n", o.image.c_str(), test.width, test.height,
                o.reference.c_str());
    std::printf("%-24s %14s\n", "metric", "value");
    for (const auto& [k, v] : values)
      if (!isParameter(k)) std::printf("%-24s %14s\n", k.c_str(), formatValue(v).c_str());
    for (const auto& [k, v] : values)
      if (isParameter(k))
        std::printf("%-24s %14s  (parameter)\n", k.c_str(), formatValue(v).c_str());
    if (!o.heatmap.empty())
      std::printf("wrote %s (%s heat map, viridis over [0, %s])\n", o.heatmap.c_str(),
                  o.heatmapMetric.c_str(), formatValue(heatMax).c_str());
  }
  for (const std::string& f : failures) std::fprintf(stderr, "diptych: threshold: %s\n", f.c_str());
  return failures.empty() ? 0 : 1;
}

}  // namespace

void addDiffCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<DiffOptions>();
  CLI::App* cmd = app.add_subcommand(
      "diff", "Compare an image with a reference: error metrics, heat map, thresholds");
  cmd->add_option("image", options->image, "Image to evaluate (PNG, EXR, HDR, ...)")->required();
  cmd->add_option("reference", options->reference, "Reference image (same size)")->required();
  cmd->add_option("--metrics", options->metrics,
                  "Comma-separated subset of mse,rmse,relmse,psnr,ssim,flip (default: all)")
      ->check([](const std::string& text) -> std::string {
        for (const std::string& m : splitList(text))
          if (std::find(metricGroupNames().begin(), metricGroupNames().end(), m) ==
              metricGroupNames().end())
            return unknownName("metric", m, metricGroupNames());
        if (splitList(text).empty()) return "empty metric list";
        return {};
      });
  cmd->add_option("--heatmap", options->heatmap,
                  "Write a viridis heat map of the error (.png, .jpg, .exr or .hdr)")
      ->check([](const std::string& path) -> std::string {
        std::string e = std::filesystem::path(path).extension().string();
        for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
        if (e == ".png" || e == ".jpg" || e == ".exr" || e == ".hdr") return {};
        return "unsupported heat map extension '" + e + "' (use .png, .jpg, .exr or .hdr)";
      });
  cmd->add_option("--heatmap-metric", options->heatmapMetric,
                  "Error shown in the heat map: flip (default) or mse (squared error)")
      ->check(CLI::IsMember({"flip", "mse"}));
  cmd->add_option("--heatmap-max", options->heatmapMax,
                  "Error mapped to the top colour (default: 1 for flip, the maximum for mse)")
      ->check(finitePositive);
  cmd->add_flag("--json", options->json, "Print JSON instead of a table");
  cmd->add_option("--fail-above", options->failAbove,
                  "METRIC=VALUE: exit 1 when METRIC exceeds VALUE (repeatable)");
  cmd->add_option("--fail-below", options->failBelow,
                  "METRIC=VALUE: exit 1 when METRIC is below VALUE (e.g. ssim, psnr)");
  cmd->add_option("--psnr-peak", options->psnrPeak, "PSNR peak (default: the reference's maximum)")
      ->check(finitePositive);
  cmd->add_option("--ssim-data-range", options->ssimDataRange,
                  "SSIM data range (default: max - min of the reference)")
      ->check(finitePositive);
  cmd->add_option("--ppd", options->ppd, "FLIP pixels per degree (1 to 1000)")
      ->capture_default_str()
      ->check([](const std::string& text) -> std::string {
        // Checked on the text: CLI11's range message prints the bound, not the value given.
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' || !(v >= kMinFlipPpd && v <= kMaxFlipPpd))
          return fmt::format("'{}' is not a number of pixels per degree in [{:g}, {:g}]", text,
                             kMinFlipPpd, kMaxFlipPpd);
        return {};
      });
  cmd->add_option("--relmse-epsilon", options->relMseEpsilon,
                  "Relative MSE epsilon in (x-r)^2/(r^2+eps)")
      ->capture_default_str()
      ->check(finitePositive);
  // Threshold syntax is checked while parsing, so a bad one is a usage error (exit 2).
  // One METRIC=VALUE per occurrence, so a threshold never swallows the positional images.
  for (const char* name : {"--fail-above", "--fail-below"})
    cmd->get_option(name)->allow_extra_args(false)->check(
        [above = std::string(name) == "--fail-above"](const std::string& text) -> std::string {
          try {
            parseThreshold(text, above);
          } catch (const CLI::ValidationError& e) {
            return e.what();
          }
          return {};
        });
  cmd->callback([options, &exitCode] { exitCode = runDiff(*options); });
}

}  // namespace diptych::cli
