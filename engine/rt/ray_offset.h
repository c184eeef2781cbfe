#pragma once
// Robust origins and extents for secondary rays, with no fixed epsilon in world units.
//
// Origin offset: Carsten Wächter and Nikolaus Binder, "A Fast and Robust Method for Avoiding
// Self-Intersection", in Ray Tracing Gems (Haines and Akenine-Möller, eds.), Apress 2019,
// chapter 6. A reconstructed hit point carries a rounding error proportional to the magnitude
// of its coordinates, so the point is moved along the geometric normal by a number of units in
// the last place (ULPs) of each coordinate: the integer bit pattern of each float is stepped by
// kIntScale * n_i. Near the origin, where ULPs become tiny while the error of the computation
// does not, the paper falls back to a small absolute step kFloatScale * n_i below
// kOriginThreshold. The three constants are the paper's.
//
// Extension (ours): the error of p = (1-u-v) p0 + u p1 + v p2 scales with the vertices'
// coordinates, not with p's own: a large triangle passing near an axis plane gives a p_i close
// to 0 whose error is an ULP of the vertex coordinates. offsetRayOrigin(p, n, magnitude) counts
// the ULPs at max(|p_i|, magnitude_i); with magnitude = 0 it is exactly the paper's method.
// vertexMagnitude() gives the magnitude for a triangle.
#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>

#include "engine/core/math.h"

namespace diptych {

namespace ray_offset {
inline constexpr float kIntScale = 256.f;              // ULPs per unit of normal component
inline constexpr float kOriginThreshold = 1.f / 32.f;  // below this |coordinate|, absolute step
inline constexpr float kFloatScale = 1.f / 65536.f;    // absolute step per unit of normal
}  // namespace ray_offset

// One coordinate: p stepped by kIntScale * n ULPs of max(|p|, magnitude), toward sign(n).
inline float offsetCoordinate(float p, float n, float magnitude = 0.f) {
  using namespace ray_offset;
  const float reference = std::max(std::fabs(p), magnitude);
  if (reference < kOriginThreshold) return p + kFloatScale * n;
  // Truncation toward zero, as in the paper: a component below 1/256 adds no step on its axis.
  const auto ulps = static_cast<std::int32_t>(kIntScale * n);
  if (reference == std::fabs(p)) {
    // The paper's form: for p < 0 a larger bit pattern is a more negative value, so subtract.
    const std::int32_t bits = std::bit_cast<std::int32_t>(p);
    return std::bit_cast<float>(bits + (p < 0.f ? -ulps : ulps));
  }
  // Step the (positive) reference instead and carry the difference over to p. The difference
  // of two floats within a factor 2 of each other is exact (Sterbenz), so the step is exactly
  // `ulps` ULPs of the reference; adding it to the smaller p rounds by at most half an ULP of p.
  const float stepped = std::bit_cast<float>(std::bit_cast<std::int32_t>(reference) + ulps);
  return p + (stepped - reference);
}

// p: a point reconstructed on a surface; n: that surface's unit geometric normal, pointing to
// the side the new ray leaves from (flip it for rays that go through the surface).
inline vec3 offsetRayOrigin(const vec3& p, const vec3& n, const vec3& magnitude = vec3(0.f)) {
  return vec3(offsetCoordinate(p.x, n.x, magnitude.x), offsetCoordinate(p.y, n.y, magnitude.y),
              offsetCoordinate(p.z, n.z, magnitude.z));
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
