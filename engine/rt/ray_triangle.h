#pragma once
// The C++ twin of shaders/gl/ray_triangle.glsl: barycentrics of the intersection of the ray
// o + t d with the plane of triangle (p0, p1, p2), in Embree's convention
// p = (1-u-v) p0 + u p1 + v p2. Moller & Trumbore, "Fast, Minimum Storage Ray/Triangle
// Intersection", JGT 1997: with e1 = p1-p0, e2 = p2-p0, s = o-p0,
//   det = e1 . (d x e2),  u = s . (d x e2) / det,  v = d . (s x e1) / det.
// Same operations in the same order as the GLSL; a GL driver may still round differently
// (llvmpipe does, in the last bits: docs/gl.md, "The visibility variant"). The CPU passes call
// it where the G-buffer is a visibility buffer (passes/common/hits_texel.h). Not clamped to the
// triangle. Returns false when the ray is parallel to the plane
// (det == 0) or (u, v) is not finite; `uv` is then unspecified.
#include <cmath>

#include "engine/core/math.h"

namespace diptych {

// The parts that depend on the triangle and the ray's origin only: a row of pixel rays (one
// origin) over one triangle shares them (passes/common/exact_hits.cpp).
struct RayTriangleSetup {
  vec3 e1, e2, s, q;
};
inline RayTriangleSetup rayTriangleSetup(const vec3& o, const vec3& p0, const vec3& p1,
                                         const vec3& p2) {
  const vec3 e1 = p1 - p0;
  const vec3 s = o - p0;
  return {e1, p2 - p0, s, glm::cross(s, e1)};
}
// The rest, per direction d: the same operations as the GLSL's.
inline bool rayTriangleBarycentrics(const RayTriangleSetup& t, const vec3& d, vec2& uv) {
  const vec3 pv = glm::cross(d, t.e2);
  const float det = glm::dot(t.e1, pv);
  uv = vec2(glm::dot(t.s, pv), glm::dot(d, t.q)) / det;
  return det != 0.f && std::isfinite(uv.x) && std::isfinite(uv.y);
}

inline bool rayTriangleBarycentrics(const vec3& o, const vec3& d, const vec3& p0, const vec3& p1,
                                    const vec3& p2, vec2& uv) {
  return rayTriangleBarycentrics(rayTriangleSetup(o, p0, p1, p2), d, uv);
}

}  // namespace diptych
