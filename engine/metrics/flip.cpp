// FLIP and HDR-FLIP, written from the papers' descriptions:
//   P. Andersson, J. Nilsson, T. Akenine-Moller, M. Oskarsson, K. Astrom, M. D. Fairchild,
//   "FLIP: A Difference Evaluator for Alternating Images", Proc. ACM Comput. Graph. Interact.
//   Tech. (HPG) 3(2), 2020.
//   P. Andersson, J. Nilsson, P. Shirley, T. Akenine-Moller, "Visualizing Errors in Rendered
//   High Dynamic Range Images", Eurographics 2021 short papers.
// Every step, parameter and choice is listed in docs/metrics.md ("FLIP").
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "engine/metrics/internal.h"
#include "engine/metrics/metrics.h"

namespace diptych {
using namespace metrics_detail;

namespace {

using Vec3 = std::array<double, 3>;
constexpr double kPi = std::numbers::pi;

// Linear sRGB (D65) <-> CIE XYZ, IEC 61966-2-1.
Vec3 rgbToXyz(const Vec3& c) {
  return {0.4124564 * c[0] + 0.3575761 * c[1] + 0.1804375 * c[2],
          0.2126729 * c[0] + 0.7151522 * c[1] + 0.0721750 * c[2],
          0.0193339 * c[0] + 0.1191920 * c[1] + 0.9503041 * c[2]};
}
Vec3 xyzToRgb(const Vec3& c) {
  return {3.2404542 * c[0] - 1.5371385 * c[1] - 0.4985314 * c[2],
          -0.9692660 * c[0] + 1.8760108 * c[1] + 0.0415560 * c[2],
          0.0556434 * c[0] - 0.2040259 * c[1] + 1.0572252 * c[2]};
}
// Reference white: XYZ of linear RGB (1, 1, 1), as in the paper.
const Vec3 kWhite = rgbToXyz({1, 1, 1});

// YCxCz (Flohr et al.; linearized CIELAB): the opponent space in which FLIP filters.
Vec3 xyzToYcxcz(const Vec3& c) {
  const double x = c[0] / kWhite[0], y = c[1] / kWhite[1], z = c[2] / kWhite[2];
  return {116 * y - 16, 500 * (x - y), 200 * (y - z)};
}
Vec3 ycxczToXyz(const Vec3& c) {
  const double y = (c[0] + 16) / 116;
  return {kWhite[0] * (c[1] / 500 + y), kWhite[1] * y, kWhite[2] * (y - c[2] / 200)};
}

double labF(double t) {
  constexpr double d = 6.0 / 29.0;
  return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29.0;
}
// CIELAB with the same white, then the Hunt adjustment (a*, b* scaled by 0.01 L*) that makes
// chroma differences in dark regions count less.
Vec3 huntLab(const Vec3& rgb) {
  const Vec3 xyz = rgbToXyz(rgb);
  const double fx = labF(xyz[0] / kWhite[0]), fy = labF(xyz[1] / kWhite[1]),
               fz = labF(xyz[2] / kWhite[2]);
  const double L = 116 * fy - 16;
  return {L, 0.01 * L * 500 * (fx - fy), 0.01 * L * 200 * (fy - fz)};
}
// HyAB distance (Abasi et al. 2020): city-block on lightness, Euclidean on chroma.
double hyab(const Vec3& a, const Vec3& b) {
  return std::abs(a[0] - b[0]) + std::hypot(a[1] - b[1], a[2] - b[2]);
}

constexpr double kQc = 0.7;              // colour-difference exponent
constexpr double kPc = 0.4;              // fraction of the maximum error mapped below kPt
constexpr double kPt = 0.95;             // ... onto [0, kPt]
constexpr double kQf = 0.5;              // feature-difference exponent
constexpr double kFeatureWidth = 0.082;  // degrees: width of the edge/point features

// One term a * sqrt(pi / b) * exp(-pi^2 r^2 / b) of the spatial CSF approximations (r in
// degrees). The paper's table: achromatic (1, 0.0047), red-green (1, 0.0053), blue-yellow
// (34.1, 0.04) + (13.5, 0.025).
// ceil(extent) as a kernel radius; computed in double so that no extent overflows an int.
// ppd is range-checked (kMaxFlipPpd) before any filter is built, so this is only a backstop.
int kernelRadius(double extent) {
  return int(std::clamp(std::ceil(extent), 1.0, 0.5 * kMaxFlipPpd));
}

struct CsfTerm {
  double a, b;
};

// Filters a plane with the sum of the channel's CSF terms, normalized to unit sum. Each term
// is a 2D Gaussian, so the sum is done as separable passes, one per term.
Plane csfFilter(const Plane& in, const std::vector<CsfTerm>& terms, double ppd, int radius) {
  std::vector<Plane> parts;
  std::vector<double> weights;
  double total = 0;
  for (const CsfTerm& t : terms) {
    std::vector<double> g(2 * radius + 1);
    double s = 0;
    for (int i = -radius; i <= radius; ++i) {
      const double x = i / ppd;
      s += g[i + radius] = std::exp(-kPi * kPi * x * x / t.b);
    }
    // 2D kernel = amp * g(x) g(y); filter with the normalized 1D g, weigh by amp * s^2.
    for (double& v : g) v /= s;
    const double w = t.a * std::sqrt(kPi / t.b) * s * s;
    parts.push_back(convolveSeparable(in, g, g));
    weights.push_back(w);
    total += w;
  }
  Plane out(in.width, in.height);
  for (std::size_t k = 0; k < parts.size(); ++k)
    for (std::size_t i = 0; i < out.v.size(); ++i) out.v[i] += weights[k] / total * parts[k].v[i];
  return out;
}

struct Features {
  Plane edge, point;  // magnitudes of the edge and point detector responses
};

// Edge detector: first derivative of a Gaussian, point detector: second derivative; sigma =
// 0.5 * 0.082 degrees * ppd, radius ceil(3 sigma). Each 1D derivative kernel has its positive
// weights scaled to sum 1 and its negative weights to sum -1, as the paper specifies.
Features detectFeatures(const Plane& grey, double ppd) {
  const double sigma = 0.5 * kFeatureWidth * ppd;
  const int radius = kernelRadius(3 * sigma);
  const std::vector<double> g = gaussianKernel(sigma, radius);
  std::vector<double> d1(g.size()), d2(g.size());
  for (int i = -radius; i <= radius; ++i) {
    const double gi = std::exp(-0.5 * i * i / (sigma * sigma));
    d1[i + radius] = -i * gi;
    d2[i + radius] = (i * i / (sigma * sigma) - 1) * gi;
  }
  for (std::vector<double>* k : {&d1, &d2}) {
    double pos = 0, neg = 0;
    for (double v : *k) (v > 0 ? pos : neg) += v;
    for (double& v : *k) v = v > 0 ? v / pos : (v < 0 ? v / -neg : 0);
  }
  const Plane ex = convolveSeparable(grey, d1, g), ey = convolveSeparable(grey, g, d1);
  const Plane px = convolveSeparable(grey, d2, g), py = convolveSeparable(grey, g, d2);
  Features f{Plane(grey.width, grey.height), Plane(grey.width, grey.height)};
  for (std::size_t i = 0; i < grey.v.size(); ++i) {
    f.edge.v[i] = std::hypot(ex.v[i], ey.v[i]);
    f.point.v[i] = std::hypot(px.v[i], py.v[i]);
  }
  return f;
}

struct Prepared {
  std::array<Plane, 3> filtered;  // YCxCz after the CSF filters
  Features features;
};

// The per-image half of FLIP: opponent space, CSF filtering, feature detection. Input is
// linear RGB in [0, 1] (colour channels; grey broadcast).
Prepared prepare(const std::array<Plane, 3>& rgb, double ppd) {
  const int w = rgb[0].width, h = rgb[0].height;
  std::array<Plane, 3> ycc{Plane(w, h), Plane(w, h), Plane(w, h)};
  for (std::size_t i = 0; i < rgb[0].v.size(); ++i) {
    const Vec3 v = xyzToYcxcz(rgbToXyz({rgb[0].v[i], rgb[1].v[i], rgb[2].v[i]}));
    for (int c = 0; c < 3; ++c) ycc[c].v[i] = v[c];
  }
  // One radius for all channels, from the widest Gaussian (b = 0.04): 3 standard deviations.
  const double bMax = 0.04;
  const int radius = kernelRadius(3 * std::sqrt(bMax / (2 * kPi * kPi)) * ppd);
  Prepared p;
  p.filtered[0] = csfFilter(ycc[0], {{1, 0.0047}}, ppd, radius);
  p.filtered[1] = csfFilter(ycc[1], {{1, 0.0053}}, ppd, radius);
  p.filtered[2] = csfFilter(ycc[2], {{34.1, 0.04}, {13.5, 0.025}}, ppd, radius);
  // Features on the achromatic channel normalized to [0, 1]: (Y' + 16) / 116 = Y / Yw.
  Plane grey(w, h);
  for (std::size_t i = 0; i < grey.v.size(); ++i) grey.v[i] = (ycc[0].v[i] + 16) / 116;
  p.features = detectFeatures(grey, ppd);
  return p;
}

Vec3 filteredToHuntLab(const Prepared& p, std::size_t i) {
  Vec3 rgb = xyzToRgb(ycxczToXyz({p.filtered[0].v[i], p.filtered[1].v[i], p.filtered[2].v[i]}));
  // The filters can leave the gamut; the paper clamps to [0, 1] before L*a*b*.
  for (double& c : rgb) c = std::clamp(c, 0.0, 1.0);
  return huntLab(rgb);
}

// LDR-FLIP of two linear RGB images in [0, 1].
Plane flipPlanes(const std::array<Plane, 3>& test, const std::array<Plane, 3>& ref, double ppd) {
  const Prepared pt = prepare(test, ppd), pr = prepare(ref, ppd);
  // Largest colour error: between Hunt-adjusted green and blue.
  const double cMax = std::pow(hyab(huntLab({0, 1, 0}), huntLab({0, 0, 1})), kQc);
  const double knee = kPc * cMax;
  Plane out(test[0].width, test[0].height);
  for (std::size_t i = 0; i < out.v.size(); ++i) {
    const double dc = std::pow(hyab(filteredToHuntLab(pt, i), filteredToHuntLab(pr, i)), kQc);
    // Compress: [0, pc cmax] -> [0, pt] linearly, [pc cmax, cmax] -> [pt, 1].
    const double ec = dc < knee ? kPt / knee * dc : kPt + (dc - knee) / (cMax - knee) * (1 - kPt);
    const double de = std::abs(pt.features.edge.v[i] - pr.features.edge.v[i]);
    const double dp = std::abs(pt.features.point.v[i] - pr.features.point.v[i]);
    const double ef = std::pow(std::max(de, dp) / std::numbers::sqrt2, kQf);
    out.v[i] = std::clamp(std::pow(ec, 1 - ef), 0.0, 1.0);
  }
  return out;
}

std::array<Plane, 3> rgbPlanes(const Image& image) {
  return {channelPlane(image, 0), channelPlane(image, colourChannels(image) == 1 ? 0 : 1),
          channelPlane(image, colourChannels(image) == 1 ? 0 : 2)};
}

Image toImage(const Plane& p) {
  Image img(p.width, p.height, 1);
  for (std::size_t i = 0; i < p.v.size(); ++i) img.pixels[i] = float(p.v[i]);
  return img;
}

// The ACES filmic fit of Narkowicz (2015) with its 0.6 pre-exposure folded into the
// coefficients, as HDR-FLIP uses: t(x) = (a x^2 + b x) / (c x^2 + d x + e).
constexpr double kTa = 0.6 * 0.6 * 2.51, kTb = 0.6 * 0.03, kTc = 0.6 * 0.6 * 2.43, kTd = 0.6 * 0.59,
                 kTe = 0.14;
double toneMap(double x) {
  x = std::max(x, 0.0);
  return std::clamp((kTa * x * x + kTb * x) / (kTc * x * x + kTd * x + kTe), 0.0, 1.0);
}

}  // namespace

FlipResult ldrFlip(const Image& test, const Image& reference, double pixelsPerDegree) {
  checkComparable(test, reference, MetricOptions{});
  std::array<Plane, 3> t = rgbPlanes(test), r = rgbPlanes(reference);
  for (auto* planes : {&t, &r})
    for (Plane& p : *planes)
      for (double& v : p.v) v = std::clamp(v, 0.0, 1.0);
  FlipResult result;
  result.map = toImage(flipPlanes(t, r, pixelsPerDegree));
  return result;
}

FlipResult hdrFlip(const Image& test, const Image& reference, double pixelsPerDegree) {
  checkComparable(test, reference, MetricOptions{});
  const std::array<Plane, 3> t = rgbPlanes(test), r = rgbPlanes(reference);
  // Exposure range from the reference's luminance: the brightest pixel and the median pixel
  // each map to 0.85 after tone mapping at the start and stop exposures.
  std::vector<double> lum(r[0].v.size());
  for (std::size_t i = 0; i < lum.size(); ++i)
    lum[i] = std::max(0.0, rgbToXyz({r[0].v[i], r[1].v[i], r[2].v[i]})[1]);
  // x with t(x) = 0.85: (a - 0.85 c) x^2 + (b - 0.85 d) x - 0.85 e = 0, positive root.
  const double qa = kTa - 0.85 * kTc, qb = kTb - 0.85 * kTd, qc = -0.85 * kTe;
  const double xMax = (-qb + std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
  std::vector<double> positive;
  for (double l : lum)
    if (l > 0) positive.push_back(l);
  FlipResult result;
  result.hdr = true;
  if (positive.empty()) {
    // All-black reference: one exposure, the images as they are.
    result.exposureStart = result.exposureStop = 0;
    result.exposureCount = 1;
  } else {
    // Choice (docs/metrics.md): the median over pixels with positive luminance, so a mostly
    // black reference still gives a finite stop exposure.
    const double yMax = *std::max_element(positive.begin(), positive.end());
    const double yMedian = percentile(positive, 50);
    result.exposureStart = std::log2(xMax / yMax);
    result.exposureStop = std::log2(xMax / yMedian);
    result.exposureCount = std::clamp(int(std::ceil(result.exposureStop - result.exposureStart)), 2,
                                      kMaxHdrFlipExposures);
  }
  Plane best(test.width, test.height, 0.0);
  for (int k = 0; k < result.exposureCount; ++k) {
    const double exposure =
        result.exposureCount == 1
            ? result.exposureStart
            : result.exposureStart +
                  k * (result.exposureStop - result.exposureStart) / (result.exposureCount - 1);
    const double scale = std::exp2(exposure);
    std::array<Plane, 3> te = t, re = r;
    for (int c = 0; c < 3; ++c) {
      for (double& v : te[c].v) v = toneMap(v * scale);
      for (double& v : re[c].v) v = toneMap(v * scale);
    }
    const Plane e = flipPlanes(te, re, pixelsPerDegree);
    for (std::size_t i = 0; i < best.v.size(); ++i) best.v[i] = std::max(best.v[i], e.v[i]);
  }
  result.map = toImage(best);
  return result;
}

}  // namespace diptych
