#include "engine/metrics/signal_metrics.h"

#include <algorithm>
#include <cmath>
#include <utility>

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

double ShadowArtifacts::acneRate() const {
  return litOutside ? double(acne) / double(litOutside) : 0.0;
}
double ShadowArtifacts::peterPanningRate() const {
  return shadowOutside ? double(peterPanning) / double(shadowOutside) : 0.0;
}
double ShadowArtifacts::lightLeakRate() const {
  return shadowOutside ? double(lightLeak) / double(shadowOutside) : 0.0;
}
double ShadowArtifacts::misclassified() const {
  const long long outside = litOutside + shadowOutside;
  return outside ? double(acne + peterPanning + lightLeak) / double(outside) : 0.0;
}

ShadowArtifacts classifyShadows(const std::vector<float>& approx, const std::vector<float>& exact,
                                const std::vector<std::uint8_t>& mask, int w, int h,
                                const std::vector<float>& footprint, int band, int reach,
                                const ShadowContacts* contacts) {
  const std::size_t n = std::size_t(w) * h;
  if (!footprint.empty() && footprint.size() != n)
    throw Error("classifyShadows: the footprint must have width x height values");
  if (contacts && (contacts->contact.size() != n || contacts->object.size() != n))
    throw Error("classifyShadows: the contacts must have width x height values");
  // The band and the displacement are compareVisibility's (one definition of both).
  const VisibilityConfusion c = compareVisibility(approx, exact, mask, w, h, band);
  auto lit = [](float v) { return v >= 0.5f; };
  auto at = [&](int x, int y) { return std::size_t(y) * w + x; };
  // Chebyshev distance to the nearest exact boundary (band) and to the nearest exactly lit
  // receiver (peter-panning vs leak): two-pass chamfer transforms with unit 8-neighbour steps,
  // which are exact for the Chebyshev metric.
  const int far = w + h;
  // `joined(i, j)`: whether a step between neighbouring pixels i and j may be taken.
  auto distanceTo = [&](auto&& seed, auto&& joined) {
    std::vector<int> d(n, far);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) d[at(x, y)] = seed(x, y) ? 0 : far;
    auto relax = [&](int x, int y, int dx, int dy) {
      const int xx = x + dx, yy = y + dy;
      if (xx >= 0 && yy >= 0 && xx < w && yy < h && joined(at(x, y), at(xx, yy)))
        d[at(x, y)] = std::min(d[at(x, y)], d[at(xx, yy)] + 1);
    };
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (auto [dx, dy] : {std::pair{-1, 0}, {-1, -1}, {0, -1}, {1, -1}}) relax(x, y, dx, dy);
    for (int y = h - 1; y >= 0; --y)
      for (int x = w - 1; x >= 0; --x)
        for (auto [dx, dy] : {std::pair{1, 0}, {1, 1}, {0, 1}, {-1, 1}}) relax(x, y, dx, dy);
    return d;
  };
  const auto anyStep = [](std::size_t, std::size_t) { return true; };
  const std::vector<int> toBoundary = distanceTo(
      [&](int x, int y) {
        if (!mask[at(x, y)]) return false;
        const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
        for (int k = 0; k < 4; ++k)
          if (nx[k] >= 0 && ny[k] >= 0 && nx[k] < w && ny[k] < h && mask[at(nx[k], ny[k])] &&
              lit(exact[at(nx[k], ny[k])]) != lit(exact[at(x, y)]))
            return true;
        return false;
      },
      anyStep);
  // Peter-panning vs leak: the distance to a contact pixel, walking only over pixels of the same
  // object (a chamfer transform with barriers: approximate around concave outlines); without
  // contacts, the distance to an exactly lit pixel.
  const std::vector<int> toContact =
      contacts ? distanceTo([&](int x, int y) { return contacts->contact[at(x, y)] != 0; },
                            [&](std::size_t i, std::size_t j) {
                              return contacts->object[i] == contacts->object[j];
                            })
               : distanceTo([&](int x, int y) { return mask[at(x, y)] && lit(exact[at(x, y)]); },
                            anyStep);

  ShadowArtifacts a;
  a.band = band;
  a.reach = reach;
  a.classes.assign(n, ShadowClass::Background);
  double absError = 0, bandFootprint = 0;
  long long bandPixels = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!mask[i]) continue;
    ++a.receivers;
    absError += std::abs(double(approx[i]) - double(exact[i]));
    const bool e = lit(exact[i]), m = lit(approx[i]), inBand = toBoundary[i] <= band;
    if (inBand && !footprint.empty()) {
      bandFootprint += footprint[i];
      ++bandPixels;
    }
    if (!inBand) ++(e ? a.litOutside : a.shadowOutside);
    ShadowClass& k = a.classes[i];
    if (e == m)
      k = e ? ShadowClass::Lit : ShadowClass::Shadow;
    else if (inBand)
      k = e ? ShadowClass::BoundaryShadow : ShadowClass::BoundaryLit;
    else if (e)
      k = ShadowClass::Acne;
    else
      k = toContact[i] <= reach ? ShadowClass::PeterPanning : ShadowClass::LightLeak;
    a.contacts += contacts && contacts->contact[i];
    a.acne += k == ShadowClass::Acne;
    a.peterPanning += k == ShadowClass::PeterPanning;
    a.lightLeak += k == ShadowClass::LightLeak;
    a.boundaryErrors += k == ShadowClass::BoundaryLit || k == ShadowClass::BoundaryShadow;
  }
  a.meanAbsError = a.receivers ? absError / double(a.receivers) : 0.0;
  a.displacementPx = c.meanBoundaryDisplacement;
  a.displacementWorld =
      bandPixels ? c.meanBoundaryDisplacement * bandFootprint / double(bandPixels) : 0.0;
  return a;
}

Image shadowClassImage(const ShadowArtifacts& a, int w, int h) {
  // Background black, lit light grey, shadow dark grey, acne red, peter-panning blue, leak
  // yellow, boundary errors (either way) magenta. Linear values.
  static const float palette[8][3] = {
      {0, 0, 0},          {0.6f, 0.6f, 0.6f}, {0.08f, 0.08f, 0.08f}, {0.9f, 0.02f, 0.02f},
      {0.02f, 0.2f, 1.f}, {1.f, 0.85f, 0.f},  {0.8f, 0.f, 0.8f},     {0.8f, 0.f, 0.8f}};
  if (a.classes.size() != std::size_t(w) * h)
    throw Error("shadowClassImage: the class map is not width x height");
  Image img(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int ch = 0; ch < 3; ++ch)
        img.at(x, y, ch) = palette[int(a.classes[std::size_t(y) * w + x])][ch];
  return img;
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
