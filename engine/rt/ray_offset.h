#pragma once
// Robust origins and extents for secondary rays, with no fixed epsilon in world units: every
// offset and margin is relative to the magnitude of the coordinates involved, so a scene scaled
// by 1e-6 or 1e6 gets the same rays up to scale (docs/numerics.md).
//
// Origin offset: the error-bound method of pbrt-v4 (Pharr, Jakob, Humphreys, "Physically Based
// Rendering", 4th ed., section 6.8.6 "Robust Spawned Ray Origins"): the reconstructed hit point
// p lies within an error box of its true surface, so the origin is moved along the geometric
// normal n by d = |n| . error and each coordinate is then rounded one more float away from the
// surface, so the addition's own rounding cannot pull it back.
//
// The error box has two terms:
//   e_i = kAxisOffset * max(|p_i|, magnitude_i) + kCrossOffset * M,   M = max_i of the same.
// The first is the rounding of p_i itself. p = (1-u-v) p0 + u p1 + v p2 is rounded at the scale
// of the vertices, not of p (a large triangle passing near an axis plane gives a p_i close to 0
// whose error is an ULP of the vertex coordinates), hence magnitude = vertexMagnitude(); its
// constant, 256 FLT_EPSILON, is the size of Wächter and Binder's 256-ULP step (Ray Tracing Gems
// ch. 6) that this code used before. The second covers Embree's watertight test, which re-finds
// the surface from vertex - origin differences whose rounding mixes the axes: a tilted plane
// through y = 0 with x ~ 10 has an error ~ ulp(10) in its plane distance even where p_y = 0.
// Measured (tests/numerics/test_reintersection.cpp): 1 FLT_EPSILON already gives no self hit
// over scales and offsets 1e-6 .. 1e6; 4 is used. Neither term has an absolute floor: Wächter
// and Binder's 1/65536 fallback below |p| = 1/32 was the floor that dominated small scenes (a
// 1e-6-scaled Whitted scene lost every shadow and secondary hit, issue 13). The only floor left
// is FLT_MIN (denormals), i.e. scenes below ~1e-30 units.
//
// Users with their own surfaces (analytic quadrics, SDFs) pass their own per-axis error bound to
// offsetRayOriginByError (pbrt gives gamma(5) |p| for a reprojected sphere hit), or the
// magnitude of the coordinates their hit point was computed from to offsetRayOrigin.
#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>

#include "engine/core/math.h"

namespace diptych {

namespace ray_offset {
inline constexpr float kAxisOffset = 256.f * FLT_EPSILON;  // per unit of max(|p_i|, magnitude_i)
inline constexpr float kCrossOffset = 4.f * FLT_EPSILON;   // per unit of M, on every axis
}  // namespace ray_offset

// The next float above x (IEEE 754 nextUp; pbrt-v4's NextFloatUp): std::nextafter without the
// libm call and its errno handling, which every spawned ray paid three times (issue 14's
// profile). Same results: NaN and +inf map to themselves, +-0 to the smallest denormal.
inline float nextFloatUp(float x) {
  if (!(x < std::numeric_limits<float>::infinity())) return x;
  if (x == 0.f) return std::numeric_limits<float>::denorm_min();
  const auto bits = std::bit_cast<std::uint32_t>(x);
  return std::bit_cast<float>(x > 0.f ? bits + 1u : bits - 1u);
}
inline float nextFloatDown(float x) {
  return -nextFloatUp(-x);
}

// pbrt-v4's OffsetRayOrigin: p moved along n (unit, pointing to the side the new ray leaves
// from) past the box p +- error (per-axis absolute error bounds, >= 0).
inline vec3 offsetRayOriginByError(const vec3& p, const vec3& n, const vec3& error) {
  const float d = glm::dot(glm::abs(n), error);
  vec3 o = p + d * n;
  for (int i = 0; i < 3; ++i) {
    // Round away from the surface: the sum above was rounded to nearest, possibly back.
    if (n[i] > 0.f)
      o[i] = nextFloatUp(o[i]);
    else if (n[i] < 0.f)
      o[i] = nextFloatDown(o[i]);
  }
  return o;
}

// The error bound e above of a point p computed from coordinates of magnitude `magnitude` (per
// axis; zero: p alone). M is never below FLT_MIN, so a point exactly at the origin still moves.
inline vec3 positionErrorBound(const vec3& p, const vec3& magnitude = vec3(0.f),
                               float axisOffset = ray_offset::kAxisOffset,
                               float crossOffset = ray_offset::kCrossOffset) {
  const vec3 m = glm::max(glm::abs(p), magnitude);
  const float scale = std::max({m.x, m.y, m.z, FLT_MIN});
  return axisOffset * m + vec3(crossOffset * scale);
}

// p: a point reconstructed on a surface; n: that surface's unit geometric normal, pointing to
// the side the new ray leaves from (flip it for rays that go through the surface); magnitude:
// vertexMagnitude() of its triangle.
inline vec3 offsetRayOrigin(const vec3& p, const vec3& n, const vec3& magnitude = vec3(0.f)) {
  return offsetRayOriginByError(p, n, positionErrorBound(p, magnitude));
}

// Component-wise max |coordinate| of a triangle's vertices: the scale of the rounding error of
// any point interpolated from them.
inline vec3 vertexMagnitude(const vec3& p0, const vec3& p1, const vec3& p2) {
  return glm::max(glm::abs(p0), glm::max(glm::abs(p1), glm::abs(p2)));
}

// A shadow segment from `origin` toward the point `target` (a light position).
struct ShadowSegment {
  vec3 direction{0.f};  // unit, origin -> target
  float tfar = -1.f;    // < 0: no segment (the origin is within float noise of the target)
};

// Relative margin, in units of FLT_EPSILON, by which a shadow ray stops short of its target.
inline constexpr float kShadowMarginEpsilons = 16.f;

// The segment stops short of the target by
//   margin = kShadowMarginEpsilons * FLT_EPSILON * (distance + max_i max(|origin_i|, |target_i|)),
// i.e. relative to both the length (Embree's hit distance has a relative error of a few ULPs)
// and the coordinates (target - origin is rounded at the coordinates' scale), so that a surface
// the light itself sits on (an emitter's quad, a lamp's bulb) does not shadow its own light.
// No fixed world-space epsilon is involved.
inline ShadowSegment shadowSegmentTo(const vec3& origin, const vec3& target) {
  const vec3 d = target - origin;
  const float distance = glm::length(d);
  ShadowSegment s;
  if (!(distance > 0.f) || !std::isfinite(distance)) return s;
  const vec3 scale = glm::max(glm::abs(origin), glm::abs(target));
  const float coordinateScale = std::max(scale.x, std::max(scale.y, scale.z));
  const float margin = kShadowMarginEpsilons * FLT_EPSILON * (distance + coordinateScale);
  s.direction = d / distance;
  s.tfar = distance - margin;
  if (!(s.tfar > 0.f)) s.tfar = -1.f;
  return s;
}

}  // namespace diptych
