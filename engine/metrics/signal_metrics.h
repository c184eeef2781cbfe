#pragma once
// Per-slot signal metrics (docs/metrics.md): a producer's slot signal against the exact
// ray-traced signal on the same G-buffer pixels.
#include <cstdint>
#include <vector>

#include "engine/core/image.h"

namespace diptych {

// Light visibility of one light: classification of each receiver pixel against the exact
// visibility, with visibility >= 0.5 counting as lit. Pixels within `band` pixels (Chebyshev
// distance) of an exact shadow boundary are counted separately, because a pixel-exact boundary
// is not expected of any raster technique.
struct VisibilityConfusion {
  int band = 2;
  long long receivers = 0;  // pixels with a surface (mask true)
  long long falseShadowOutside = 0, falseLitOutside = 0, correctOutside = 0;
  long long falseShadowInside = 0, falseLitInside = 0, correctInside = 0;
  // Mean signed displacement of the approximate boundary from the exact one, in pixels, along
  // the exact visibility gradient: > 0 when the shadow grows (acne, over-darkening), < 0 when
  // it shrinks (peter-panning, leaks). For each lit exact-boundary pixel, the shadowed samples
  // of both signals are counted on the same line of +-4*band pixels across the boundary; the
  // displacement is their difference.
  double meanBoundaryDisplacement = 0;
  long long boundarySamples = 0;

  double falseShadowRate() const;  // outside the band, over receivers outside the band
  double falseLitRate() const;
};

// `mask[i]` true where a surface is seen (G-buffer coverage); visibilities are one value per
// pixel, row-major, width x height.
VisibilityConfusion compareVisibility(const std::vector<float>& approximate,
                                      const std::vector<float>& exact,
                                      const std::vector<std::uint8_t>& mask, int width, int height,
                                      int band = 2);

// Shadow artifacts of one light (docs/shadow-bias.md): each receiver pixel (mask true) is put in
// one class against the exact visibility (lit = visibility >= 0.5). Acne: false shadow farther
// than `band` pixels from an exact boundary. False light outside the band is peter-panning when
// it lies next to a contact (within `reach` pixels of a contact pixel on the same object: the
// shadow came loose where the caster touches the receiver) and a light leak otherwise (light
// through a thin caster, or a whole shadow gone, far from any contact). Without contacts (a
// caller with no rays) the proxy is distance: within `reach` of an exactly lit pixel.
// Inside the band a wrong pixel is a boundary error (the boundary moved, see displacement).
enum class ShadowClass : std::uint8_t {
  Background = 0,
  Lit,
  Shadow,
  Acne,
  PeterPanning,
  LightLeak,
  BoundaryLit,
  BoundaryShadow
};
struct ShadowArtifacts {
  int band = 2, reach = 16;
  long long receivers = 0, litOutside = 0, shadowOutside = 0;  // exact classes, outside the band
  long long acne = 0, peterPanning = 0, lightLeak = 0, boundaryErrors = 0;
  long long contacts = 0;  // contact pixels (ShadowContacts), 0 without contacts
  // Mean |approximate - exact| of the visibility values over receivers: soft filters (PCF,
  // PCSS) are scored on their value, not only after the 0.5 threshold.
  double meanAbsError = 0;
  // compareVisibility's signed boundary displacement (px, > 0: the shadow grew), and the same
  // in world units on the receiver: px times the mean pixel footprint at the sampled boundary.
  double displacementPx = 0, displacementWorld = 0;
  std::vector<ShadowClass> classes;  // per pixel, row-major

  double acneRate() const;          // acne / litOutside
  double peterPanningRate() const;  // peterPanning / shadowOutside
  double lightLeakRate() const;     // lightLeak / shadowOutside
  double misclassified() const;     // (acne + peterPanning + lightLeak) / outside-band receivers
};

// Contacts of one light, per pixel: `contact` 1 where the exact answer is shadow and the exact
// shadow ray meets its occluder within a small world distance (the caster touches the receiver
// there); `object` the receiver's id (G-buffer instance), so that false light counts as
// peter-panning only next to a contact on its own surface, not next to another object's.
struct ShadowContacts {
  std::vector<std::uint8_t> contact;
  std::vector<std::int32_t> object;
};

// `footprint`: world size of each pixel on its receiver (empty: world displacement stays 0).
// `contacts`: null for the distance proxy (see ShadowClass).
ShadowArtifacts classifyShadows(const std::vector<float>& approximate,
                                const std::vector<float>& exact,
                                const std::vector<std::uint8_t>& mask, int width, int height,
                                const std::vector<float>& footprint = {}, int band = 2,
                                int reach = 16, const ShadowContacts* contacts = nullptr);
// The class map as an RGB image (linear values of a fixed palette; see docs/shadow-bias.md).
Image shadowClassImage(const ShadowArtifacts& artifacts, int width, int height);

// Radiance error of a reflection/transmission signal (or the texture_filtering colour) over the
// pixels where the slot contributes (mask true): RMSE and relative RMSE
// sqrt(sum |a - e|^2 / sum |e|^2), on RGB.
struct SignalError {
  long long pixels = 0;
  double rmse = 0, relativeRmse = 0;
};
SignalError compareRadiance(const Image& approximate, const Image& exact,
                            const std::vector<std::uint8_t>& mask);

}  // namespace diptych
