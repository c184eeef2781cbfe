// shadow_projection.glsl: the lecture's shadow polygons (Tema 5, "Sombras arrojadas", the
// brute-force algorithm: each caster polygon projected from the light onto a receiver), one point
// at a time, written once for GLSL 4.50 and C++ under the subset rules of shading.glsl.
//
// The shadow matrix of plane P = (n, d) (n.x + d = 0) and homogeneous light L (Blinn 1988, "Me
// and my (fake) shadow") is S = (P.L) I - L P^T: S x lies on the plane and on the line through x
// and the light. Evaluated as printed, its rows subtract products of the size of the scene's
// coordinates squared, and the difference is divided by w = P.L - P.x, which goes to 0 for a
// caster at the light's distance from the plane: a caster in a plane through the light (an
// emissive quad around an area light's centre) then projected to a wide polygon instead of a
// line. The same point in the well-conditioned form used here:
//   point light (L = (l, 1)):      S x = (w l + (P.L)(x - l), w),  w = n.(l - x)  (d cancels)
//   directional (L = (l, 0), l toward the light):  S x = ((P.L) x - (P.x) l, P.L)
// With P oriented toward the light (P.L > 0), a caster point can shade the receiver only if
// 0 < P.x (the light's side) and, for a point light, w > 0 (nearer the plane than the light).
#ifndef DIPTYCH_SHADOW_PROJECTION_GLSL
#define DIPTYCH_SHADOW_PROJECTION_GLSL

#ifndef SHADING_FN
#define SHADING_FN
#endif

// S x for a caster point x: homogeneous, w as above (> 0 where x can cast on the plane).
SHADING_FN vec4 shadowProjectedPoint(vec4 plane, vec4 light, vec3 x) {
  vec3 n = vec3(plane.x, plane.y, plane.z);
  vec3 l = vec3(light.x, light.y, light.z);
  if (light.w == 0.0f) {
    float pl = dot(n, l);
    return vec4(pl * x - (dot(n, x) + plane.w) * l, pl);
  }
  float w = dot(n, l - x);
  return vec4(w * l + (dot(n, l) + plane.w) * (x - l), w);
}

#endif
