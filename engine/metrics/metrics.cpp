// computeMetrics: the chosen metric groups, with the parameters they used stated beside them.
#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/error.h"
#include "engine/core/known.h"
#include "engine/metrics/internal.h"
#include "engine/metrics/metrics.h"

namespace diptych {
using namespace metrics_detail;

namespace {

// Minimum and maximum over the reference's colour channels.
std::pair<double, double> colourRange(const Image& image) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const int cc = colourChannels(image);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < cc; ++c) {
        lo = std::min(lo, double(image.at(x, y, c)));
        hi = std::max(hi, double(image.at(x, y, c)));
      }
  return {lo, hi};
}

bool withinUnitRange(const Image& image) {
  const auto [lo, hi] = colourRange(image);
  return lo >= 0 && hi <= 1;
}

FlipResult flipFor(const Image& test, const Image& reference, double ppd) {
  // LDR-FLIP is defined for display-referred images; anything outside [0, 1] is HDR.
  return withinUnitRange(test) && withinUnitRange(reference) ? ldrFlip(test, reference, ppd)
                                                             : hdrFlip(test, reference, ppd);
}

}  // namespace

const std::vector<std::string>& metricGroupNames() {
  static const std::vector<std::string> names{"mse", "rmse", "relmse", "psnr", "ssim", "flip"};
  return names;
}

std::map<std::string, double> computeMetrics(const Image& test, const Image& reference,
                                             const MetricOptions& options) {
  for (const std::string& m : options.metrics)
    if (std::find(metricGroupNames().begin(), metricGroupNames().end(), m) ==
        metricGroupNames().end())
      throw InputError("metrics", "", unknownName("metric", m, metricGroupNames()));
  checkComparable(test, reference, options);
  auto wanted = [&](const char* name) {
    return options.metrics.empty() ||
           std::find(options.metrics.begin(), options.metrics.end(), name) != options.metrics.end();
  };
  std::map<std::string, double> out;
  if (wanted("mse") || wanted("rmse") || wanted("psnr")) {
    const double m = meanSquaredError(test, reference);
    if (wanted("mse")) out["mse"] = m;
    if (wanted("rmse")) out["rmse"] = std::sqrt(m);
    if (wanted("psnr")) {
      // The reference's maximum unless told; an all-black reference falls back to 1.
      double peak = options.psnrPeak;
      if (peak <= 0) peak = colourRange(reference).second;
      if (peak <= 0) peak = 1;
      out["psnr_peak"] = peak;
      out["psnr"] =
          m == 0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(peak * peak / m);
    }
  }
  if (wanted("relmse"))
    out["relmse"] = relativeMeanSquaredError(test, reference, options.relMseEpsilon);
  if (wanted("ssim")) {
    double range = options.ssimDataRange;
    if (range <= 0) {
      const auto [lo, hi] = colourRange(reference);
      range = hi - lo;
    }
    if (range <= 0) range = 1;  // constant reference: no range to measure; use 1
    out["ssim_data_range"] = range;
    out["ssim"] = ssim(test, reference, range);
  }
  if (wanted("flip")) {
    const FlipResult f = flipFor(test, reference, options.flipPixelsPerDegree);
    std::vector<double> values(f.map.pixels.begin(), f.map.pixels.end());
    double sum = 0;
    for (double v : values) sum += v;
    out["flip_mean"] = sum / double(values.size());
    out["flip_p50"] = percentile(values, 50);
    out["flip_p95"] = percentile(values, 95);
    out["flip_p99"] = percentile(values, 99);
    out["flip_variant"] = f.hdr ? 1 : 0;
    out["flip_pixels_per_degree"] = options.flipPixelsPerDegree;
    if (f.hdr) {
      out["flip_exposure_start"] = f.exposureStart;
      out["flip_exposure_stop"] = f.exposureStop;
      out["flip_exposure_count"] = f.exposureCount;
    }
  }
  return out;
}

Image flipErrorMap(const Image& test, const Image& reference, const MetricOptions& options) {
  checkComparable(test, reference, options);
  return flipFor(test, reference, options.flipPixelsPerDegree).map;
}

}  // namespace diptych
