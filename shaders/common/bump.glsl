// bump.glsl: the lecture's normal perturbation from a height field (Tema 5, "Perturbación de la
// normal": "Rugosidades definidas por un campo de alturas"), written once for GLSL 4.50 and C++
// under the subset rules at the top of shading.glsl (include that file first).
//
//   d_u ~= k (f_h(u + D, v) - f_h(u - D, v)) / (2 D)     d_v likewise in v
//   t'_u = t_u + d_u n      t'_v = t_v + d_v n      n' = normalize(t'_u x t'_v)
//
// t_u, t_v: dP/du, dP/dv of the surface (not normalised: their lengths give the height field's
// scale); n: unit normal; k scales the relief, D is about one texel (1 / n_t).
// One addition, on purpose: the lecture takes n collinear with t_u x t_v. With glTF's uv (v
// grows down the image) t_u x t_v points against the front normal on ordinary meshes, so n' is
// turned to the side of n when they disagree; otherwise the formula is as printed.
#ifndef DIPTYCH_BUMP_GLSL
#define DIPTYCH_BUMP_GLSL

// k (f(+D) - f(-D)) / (2 D); 0 when D is not positive.
SHADING_FN float bumpSlope(float heightPlus, float heightMinus, float k, float delta) {
  if (!(delta > 0.0f)) return 0.0f;
  return k * (heightPlus - heightMinus) / (2.0f * delta);
}

// n' from t_u, t_v, n and the slopes d_u, d_v. Degenerate input (parallel tangents, zero
// vectors) returns the unit n.
SHADING_FN vec3 bumpNormal(vec3 tu, vec3 tv, vec3 n, float du, float dv) {
  vec3 N = safeNormalize(n);
  vec3 tuPrime = tu + du * N;
  vec3 tvPrime = tv + dv * N;
  vec3 m = safeNormalize(cross(tuPrime, tvPrime));
  if (maxAbsComponent(m) == 0.0f) return N;
  float side = dot(cross(tu, tv), N);
  return side < 0.0f ? -m : m;
}

#endif  // DIPTYCH_BUMP_GLSL
