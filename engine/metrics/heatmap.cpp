// Heat maps with the viridis colour map (van der Walt and Smith, matplotlib 2.0, 2015), which
// is perceptually uniform, readable in greyscale and by colour-blind viewers.
#include <algorithm>
#include <array>
#include <cmath>

#include "engine/metrics/metrics.h"

namespace diptych {
namespace {

// Degree-6 polynomial fit of viridis (sRGB-encoded output), published by Matt Zucconi
// ("mattz") in the Shadertoy "Perceptual colormaps" (https://www.shadertoy.com/view/WlfXRN,
// CC0), fitted to matplotlib's table. Coefficient k holds the t^k terms for R, G, B.
constexpr std::array<std::array<double, 3>, 7> kViridis{{
    {0.2777273272234177, 0.005407344544966578, 0.3340998053353061},
    {0.1050930431085774, 1.404613529898575, 1.384590162594685},
    {-0.3308618287255563, 0.214847559468213, 0.09509516302823659},
    {-4.634230498983486, -5.799100973351585, -19.33244095627987},
    {6.228269936347081, 14.17993336680509, 56.69055260068105},
    {4.776384997670288, -13.74514537774601, -65.35303263337234},
    {-5.435455855934631, 4.645852612178535, 26.3124352495832},
}};

}  // namespace

std::array<float, 3> viridisSrgb(float t) {
  const double x = std::clamp(double(t), 0.0, 1.0);
  std::array<float, 3> out{};
  for (int c = 0; c < 3; ++c) {
    double v = 0;
    for (int k = 6; k >= 0; --k) v = v * x + kViridis[k][c];  // Horner
    out[c] = float(std::clamp(v, 0.0, 1.0));
  }
  return out;
}

Image heatMap(const Image& values, float maxValue) {
  Image out(values.width, values.height, 3);
  const float scale = maxValue > 0 ? 1.f / maxValue : 0.f;
  for (int y = 0; y < values.height; ++y)
    for (int x = 0; x < values.width; ++x) {
      const float v = values.at(x, y, 0);
      const std::array<float, 3> c = viridisSrgb(std::isfinite(v) ? v * scale : 1.f);
      // The table is display-encoded; images hold linear values (writeImage re-encodes).
      for (int k = 0; k < 3; ++k) out.at(x, y, k) = srgbToLinear(c[k]);
    }
  return out;
}

}  // namespace diptych
