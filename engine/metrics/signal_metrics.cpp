#include "engine/metrics/signal_metrics.h"

#include <cmath>

#include "engine/core/error.h"

namespace diptych {

double VisibilityConfusion::falseShadowRate() const {
  const long long outside = falseShadowOutside + falseLitOutside + correctOutside;
  return outside ? double(falseShadowOutside) / double(outside) : 0.0;
}

double VisibilityConfusion::falseLitRate() const {
  const long long outside = falseShadowOutside + falseLitOutside + correctOutside;
  return outside ? double(falseLitOutside) / double(outside) : 0.0;
}

VisibilityConfusion compareVisibility(const std::vector<float>& approx,
                                      const std::vector<float>& exact,
                                      const std::vector<std::uint8_t>& mask, int w, int h,
                                      int band) {
  const std::size_t n = std::size_t(w) * h;
  if (approx.size() != n || exact.size() != n || mask.size() != n)
    throw Error("compareVisibility: signals and mask must all have width x height values");
  auto lit = [](float v) { return v >= 0.5f; };
  auto at = [&](int x, int y) { return std::size_t(y) * w + x; };
  // Exact boundary pixels: a covered pixel with a covered 4-neighbour of the other class.
  std::vector<std::uint8_t> boundary(n, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!mask[at(x, y)]) continue;
      const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
      for (int k = 0; k < 4; ++k)
        if (nx[k] >= 0 && ny[k] >= 0 && nx[k] < w && ny[k] < h && mask[at(nx[k], ny[k])] &&
            lit(exact[at(nx[k], ny[k])]) != lit(exact[at(x, y)]))
          boundary[at(x, y)] = 1;
    }
  // Band: within `band` pixels (Chebyshev) of a boundary pixel; separable max filter.
  std::vector<std::uint8_t> rows(n, 0), inBand(n, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int d = -band; d <= band && !rows[at(x, y)]; ++d)
        if (x + d >= 0 && x + d < w && boundary[at(x + d, y)]) rows[at(x, y)] = 1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int d = -band; d <= band && !inBand[at(x, y)]; ++d)
        if (y + d >= 0 && y + d < h && rows[at(x, y + d)]) inBand[at(x, y)] = 1;

  VisibilityConfusion c;
  c.band = band;
  for (std::size_t i = 0; i < n; ++i) {
    if (!mask[i]) continue;
    ++c.receivers;
    const bool a = lit(approx[i]), e = lit(exact[i]);
    long long& correct = inBand[i] ? c.correctInside : c.correctOutside;
    long long& falseShadow = inBand[i] ? c.falseShadowInside : c.falseShadowOutside;
    long long& falseLit = inBand[i] ? c.falseLitInside : c.falseLitOutside;
    if (a == e)
      ++correct;
    else if (e)
      ++falseShadow;
    else
      ++falseLit;
  }
  // Signed displacement: along the exact visibility gradient through each lit boundary pixel,
  // count the shadowed samples of each signal over the same line; their difference is how far
  // the approximate boundary sits from the exact one (> 0: the shadow grew). Counting both
  // signals on the same rounded samples makes identical signals give exactly 0.
  double sum = 0;
  const int reach = 4 * std::max(band, 1);
  for (int y = 1; y + 1 < h; ++y)
    for (int x = 1; x + 1 < w; ++x) {
      const std::size_t i = at(x, y);
      if (!boundary[i] || !lit(exact[i])) continue;
      const float gx = exact[at(x + 1, y)] - exact[at(x - 1, y)];
      const float gy = exact[at(x, y + 1)] - exact[at(x, y - 1)];
      const float len = std::hypot(gx, gy);
      if (!(len > 0.f)) continue;
      int approxShadow = 0, exactShadow = 0;
      for (int k = -reach; k <= reach; ++k) {
        const int px = int(std::lround(x + k * gx / len)), py = int(std::lround(y + k * gy / len));
        if (px < 0 || py < 0 || px >= w || py >= h || !mask[at(px, py)]) continue;
        approxShadow += lit(approx[at(px, py)]) ? 0 : 1;
        exactShadow += lit(exact[at(px, py)]) ? 0 : 1;
      }
      sum += approxShadow - exactShadow;
      ++c.boundarySamples;
    }
  c.meanBoundaryDisplacement = c.boundarySamples ? sum / double(c.boundarySamples) : 0.0;
  return c;
}

SignalError compareRadiance(const Image& a, const Image& e, const std::vector<std::uint8_t>& mask) {
  if (a.width != e.width || a.height != e.height ||
      mask.size() != std::size_t(a.width) * a.height || a.channels < 3 || e.channels < 3)
    throw Error("compareRadiance: images and mask must have the same size and RGB channels");
  SignalError s;
  double num = 0, den = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if (!mask[std::size_t(y) * a.width + x]) continue;
      ++s.pixels;
      for (int c = 0; c < 3; ++c) {
        const double d = double(a.at(x, y, c)) - e.at(x, y, c);
        num += d * d;
        den += double(e.at(x, y, c)) * e.at(x, y, c);
      }
    }
  if (s.pixels) {
    s.rmse = std::sqrt(num / double(3 * s.pixels));
    s.relativeRmse = den > 0 ? std::sqrt(num / den) : (num > 0 ? INFINITY : 0.0);
  }
  return s;
}

}  // namespace diptych
