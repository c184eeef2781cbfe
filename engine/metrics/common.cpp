#include <tbb/parallel_for.h>

#include <fmt/format.h>
#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/metrics/internal.h"

namespace diptych::metrics_detail {

int colourChannels(const Image& image) {
  return image.channels >= 3 ? 3 : 1;
}

void checkComparable(const Image& test, const Image& reference, const MetricOptions& options) {
  if (test.empty() || reference.empty())
    throw InputError(test.empty() ? options.testName : options.referenceName, "",
                     "image has no pixels");
  if (test.width != reference.width || test.height != reference.height)
    throw InputError(
        options.testName, "",
        fmt::format("size {}x{} differs from the reference {} ({}x{})", test.width, test.height,
                    options.referenceName, reference.width, reference.height));
  for (const auto* img : {&test, &reference}) {
    const int cc = colourChannels(*img);
    for (int y = 0; y < img->height; ++y)
      for (int x = 0; x < img->width; ++x)
        for (int c = 0; c < cc; ++c)
          if (!std::isfinite(img->at(x, y, c)))
            throw InputError(img == &test ? options.testName : options.referenceName,
                             fmt::format("pixel ({}, {}) channel {}", x, y, c),
                             "value is not finite; metrics would be undefined");
  }
}

Plane channelPlane(const Image& image, int c) {
  Plane p(image.width, image.height);
  const int src = colourChannels(image) == 1 ? 0 : c;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) p(x, y) = image.at(x, y, src);
  return p;
}

Plane convolveSeparable(const Plane& in, const std::vector<double>& kx,
                        const std::vector<double>& ky) {
  const int w = in.width, h = in.height;
  const int rx = int(kx.size() / 2), ry = int(ky.size() / 2);
  Plane tmp(w, h), out(w, h);
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      double s = 0;
      for (int i = -rx; i <= rx; ++i) s += kx[i + rx] * in(std::clamp(x + i, 0, w - 1), y);
      tmp(x, y) = s;
    }
  });
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      double s = 0;
      for (int j = -ry; j <= ry; ++j) s += ky[j + ry] * tmp(x, std::clamp(y + j, 0, h - 1));
      out(x, y) = s;
    }
  });
  return out;
}

std::vector<double> gaussianKernel(double sigma, int radius) {
  std::vector<double> k(2 * radius + 1);
  double sum = 0;
  for (int i = -radius; i <= radius; ++i)
    sum += k[i + radius] = std::exp(-0.5 * i * i / (sigma * sigma));
  for (double& v : k) v /= sum;
  return k;
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  // Rank p/100 * (n - 1), interpolating between the two neighbouring order statistics.
  const double rank = std::clamp(p, 0.0, 100.0) / 100.0 * double(values.size() - 1);
  const std::size_t lo = std::size_t(std::floor(rank));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  std::nth_element(values.begin(), values.begin() + lo, values.end());
  const double a = values[lo];
  const double b = hi == lo ? a : *std::min_element(values.begin() + lo + 1, values.end());
  return a + (rank - double(lo)) * (b - a);
}

}  // namespace diptych::metrics_detail
