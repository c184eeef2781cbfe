#pragma once
// Helpers shared by the metric implementations (not part of the public API).
#include <cstddef>
#include <string>
#include <vector>

#include "engine/core/image.h"
#include "engine/metrics/metrics.h"

namespace diptych::metrics_detail {

// One channel of an image as doubles, row-major, row 0 on top.
struct Plane {
  int width = 0, height = 0;
  std::vector<double> v;
  Plane() = default;
  Plane(int w, int h, double fill = 0) : width(w), height(h), v(std::size_t(w) * h, fill) {}
  double& operator()(int x, int y) { return v[std::size_t(y) * width + x]; }
  double operator()(int x, int y) const { return v[std::size_t(y) * width + x]; }
};

// The colour channels compared: 1 (grey, or grey + alpha) or 3 (RGB, RGBA: alpha ignored).
int colourChannels(const Image& image);

// Throws InputError naming both images when the sizes differ, or when a colour value is not
// finite (every metric would be NaN, so we say where the first bad value is instead).
void checkComparable(const Image& test, const Image& reference, const MetricOptions& options);

// Channel c of the image's colour channels; a grey image is broadcast when `channels` is 3.
Plane channelPlane(const Image& image, int c);

// Separable correlation with clamp-to-edge borders. Kernels have odd length, centred.
Plane convolveSeparable(const Plane& in, const std::vector<double>& kx,
                        const std::vector<double>& ky);

// Sampled Gaussian exp(-x^2 / (2 sigma^2)) for x in [-radius, radius], normalized to sum 1.
std::vector<double> gaussianKernel(double sigma, int radius);

// Linear-interpolated percentile (numpy's default "linear" method), p in [0, 100].
double percentile(std::vector<double> values, double p);

}  // namespace diptych::metrics_detail
