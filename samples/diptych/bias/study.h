#pragma once
// `diptych shadow-bias` (docs/shadow-bias.md): one sweep per bias mode of the shadow_map
// producer (its amount over a range that spans acne to peter-panning, at several map
// resolutions, filters and sun elevations) against rt_shadows, then per curve the analytic
// prediction, the measured acne crossing and the best amount.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace diptych::cli {

struct BiasStudyOptions {
  std::string scene;
  std::vector<std::string> modes = {"none",          "constant",       "slope",
                                    "normal_offset", "receiver_plane", "adaptive"};
  std::vector<int> resolutions = {256, 1024};
  std::vector<double> elevations = {15, 40, 70};  // degrees; only for a directional light
  std::vector<std::string> filters = {"none"};
  int points = 13;  // amounts per mode, log spaced
  int width = 320, height = 240, frames = 1, warmup = 0, light = 0;
  std::string receiver;
  double contact = -1;  // SweepOptions::contact
  std::filesystem::path out = "shadow-bias";
};

// The swept amount of each mode ("" for none), and its analytic threshold, when there is one, in
// that amount's units: constant (w/2) tan(theta) world units; normal_offset 1/2 (texel
// footprints); slope 1/2 (axis-aligned depth slope; up to 1 diagonally).
std::string biasAmountKey(const std::string& mode);
double predictedThreshold(const std::string& mode, double texelWorld, double incidenceDeg);

// Runs (or resumes) every mode's sweep under out/MODE/ and returns summary.json's document.
nlohmann::json runBiasStudy(const BiasStudyOptions& options);

// Amount at which `rate` first drops below `level` along increasing amounts (log-interpolated
// between the last point at or above and the first below); 0 when it never was at or above;
// -1 when it never drops below.
double crossing(const std::vector<double>& amounts, const std::vector<double>& rates, double level);

}  // namespace diptych::cli
