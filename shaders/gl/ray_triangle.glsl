// Barycentrics of the intersection of the ray o + t d with the plane of triangle (p0, p1, p2),
// in Embree's convention p = (1-u-v) p0 + u p1 + v p2. Moller & Trumbore, "Fast, Minimum Storage
// Ray/Triangle Intersection", JGT 1997: with e1 = p1-p0, e2 = p2-p0, s = o-p0,
//   det = e1 . (d x e2),  u = s . (d x e2) / det,  v = d . (s x e1) / det.
// The result is not clamped to the triangle: at a pixel centre the rasterizer assigned to this
// triangle, (u, v) may leave [0,1] by rounding, and the unclamped value keeps the point on the ray.
// Returns false when the ray is parallel to the plane (det == 0 or not finite).
bool rayTriangleBarycentrics(vec3 o, vec3 d, vec3 p0, vec3 p1, vec3 p2, out vec2 uv) {
  vec3 e1 = p1 - p0;
  vec3 e2 = p2 - p0;
  vec3 pv = cross(d, e2);
  float det = dot(e1, pv);
  vec3 s = o - p0;
  vec3 q = cross(s, e1);
  uv = vec2(dot(s, pv), dot(d, q)) / det;
  return det != 0.0 && !any(isinf(uv)) && !any(isnan(uv));
}
