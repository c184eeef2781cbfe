// MSE, RMSE, relative MSE and PSNR (docs/metrics.md, "Pixel metrics").
#include <cmath>
#include <limits>

#include "engine/metrics/internal.h"
#include "engine/metrics/metrics.h"

namespace diptych {
using namespace metrics_detail;

namespace {

// Calls f(test value, reference value) for every colour sample; returns the sample count.
template <class F>
std::size_t forEachSample(const Image& test, const Image& reference, F&& f) {
  checkComparable(test, reference, MetricOptions{});
  const int channels = std::max(colourChannels(test), colourChannels(reference));
  const int tc = colourChannels(test), rc = colourChannels(reference);
  for (int y = 0; y < test.height; ++y)
    for (int x = 0; x < test.width; ++x)
      for (int c = 0; c < channels; ++c)
        f(double(test.at(x, y, tc == 1 ? 0 : c)), double(reference.at(x, y, rc == 1 ? 0 : c)));
  return std::size_t(test.width) * test.height * channels;
}

}  // namespace

double meanSquaredError(const Image& test, const Image& reference) {
  double sum = 0;
  const std::size_t n =
      forEachSample(test, reference, [&](double t, double r) { sum += (t - r) * (t - r); });
  return sum / double(n);
}

double relativeMeanSquaredError(const Image& test, const Image& reference, double epsilon) {
  // (x - r)^2 / (r^2 + eps): errors relative to the reference's brightness, so dark and bright
  // regions of an HDR render weigh alike (Rousselle et al. 2011 use this form for denoising).
  double sum = 0;
  const std::size_t n = forEachSample(
      test, reference, [&](double t, double r) { sum += (t - r) * (t - r) / (r * r + epsilon); });
  return sum / double(n);
}

double psnr(const Image& test, const Image& reference, double peak) {
  const double m = meanSquaredError(test, reference);
  if (m == 0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(peak * peak / m);
}

Image squaredErrorMap(const Image& test, const Image& reference) {
  checkComparable(test, reference, MetricOptions{});
  const int channels = std::max(colourChannels(test), colourChannels(reference));
  const int tc = colourChannels(test), rc = colourChannels(reference);
  Image out(test.width, test.height, 1);
  // Mean over the colour channels, so the map's mean is the MSE.
  for (int y = 0; y < test.height; ++y)
    for (int x = 0; x < test.width; ++x) {
      double s = 0;
      for (int c = 0; c < channels; ++c) {
        const double d =
            double(test.at(x, y, tc == 1 ? 0 : c)) - double(reference.at(x, y, rc == 1 ? 0 : c));
        s += d * d;
      }
      out.at(x, y, 0) = float(s / channels);
    }
  return out;
}

}  // namespace diptych
