// SSIM: Wang, Bovik, Sheikh, Simoncelli, "Image Quality Assessment: From Error Visibility to
// Structural Similarity", IEEE Trans. Image Processing 13(4), 2004. Formula and parameters in
// docs/metrics.md. Written to agree with scikit-image's structural_similarity(
// gaussian_weights=True, sigma=1.5, use_sample_covariance=False, channel_axis=-1), which
// tests/cli/ssim_vs_skimage.cmake checks.
#include <algorithm>

#include "engine/metrics/internal.h"
#include "engine/metrics/metrics.h"

namespace diptych {
using namespace metrics_detail;

namespace {

constexpr double kSigma = 1.5;
// scipy's gaussian_filter truncates at 3.5 sigma as skimage asks: radius int(3.5 * 1.5 + 0.5)
// = 5, the 11x11 window of the paper.
constexpr int kRadius = 5;
constexpr double kK1 = 0.01, kK2 = 0.03;

double channelSsim(const Plane& x, const Plane& y, double dataRange) {
  const std::vector<double> g = gaussianKernel(kSigma, kRadius);
  const int w = x.width, h = x.height;
  Plane xx(w, h), yy(w, h), xy(w, h);
  for (std::size_t i = 0; i < x.v.size(); ++i) {
    xx.v[i] = x.v[i] * x.v[i];
    yy.v[i] = y.v[i] * y.v[i];
    xy.v[i] = x.v[i] * y.v[i];
  }
  const Plane ux = convolveSeparable(x, g, g), uy = convolveSeparable(y, g, g);
  const Plane uxx = convolveSeparable(xx, g, g), uyy = convolveSeparable(yy, g, g);
  const Plane uxy = convolveSeparable(xy, g, g);
  const double c1 = (kK1 * dataRange) * (kK1 * dataRange);
  const double c2 = (kK2 * dataRange) * (kK2 * dataRange);
  // Like skimage, average only where the whole window lies inside the image, so the border
  // rule does not matter. Images smaller than the window (skimage refuses them) are averaged
  // over every pixel with clamp-to-edge borders instead.
  const bool crop = w > 2 * kRadius && h > 2 * kRadius;
  const int pad = crop ? kRadius : 0;
  double sum = 0;
  std::size_t count = 0;
  for (int j = pad; j < h - pad; ++j)
    for (int i = pad; i < w - pad; ++i) {
      const double mx = ux(i, j), my = uy(i, j);
      // Population (not sample) covariances: use_sample_covariance=False.
      const double vx = uxx(i, j) - mx * mx, vy = uyy(i, j) - my * my;
      const double cxy = uxy(i, j) - mx * my;
      sum += ((2 * mx * my + c1) * (2 * cxy + c2)) / ((mx * mx + my * my + c1) * (vx + vy + c2));
      ++count;
    }
  return sum / double(count);
}

}  // namespace

double ssim(const Image& test, const Image& reference, double dataRange) {
  checkComparable(test, reference, MetricOptions{});
  const int channels = std::max(colourChannels(test), colourChannels(reference));
  double sum = 0;
  for (int c = 0; c < channels; ++c)
    sum += channelSsim(channelPlane(test, c), channelPlane(reference, c), dataRange);
  return sum / channels;
}

}  // namespace diptych
