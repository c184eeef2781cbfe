// shading.glsl: the lecture's extended local illumination model (Tema 5, "Un M.I.L. extendido
// para Ray-Tracing", functions EVALUAMILREC and DIRECTA), written once for GLSL 4.50 and C++.
//
//   L = M_E + A_G + sum_i V_i S_i L_dir,i + k_ps M_PS L_refl + k_t M_T L_trans
//   L_dir = k_a C + k_d C max(0, n.l) + k_s d_i max(0, r.v)^e
//
// Symbols (units follow glTF KHR_lights_punctual; see docs/ray-tracing.md):
//   n  unit shading normal; v unit vector toward the viewer; l unit vector toward the light.
//   r  = 2 (n.l) n - l, the reflection of l about n (GLSL reflect(-l, n)). The lecture calls r
//      "the reflected vector, depending on v and n"; reflecting v instead gives the same r.v
//      (both equal 2 (n.l)(n.v) - l.v), so the choice does not change a value.
//   C colour, k_a/k_d/k_s coefficients, e exponent, d_i specular colour, M_E emission,
//   A_G global ambient radiance, S_i light radiance at the point, V_i visibility in [0,1].
//
// Deviation from the lecture, on purpose: the k_s term is only added when n.l > 0. As printed,
// DIRECTA gives a highlight for a light below the tangent plane (r.v can be positive there);
// the lecture itself says a source that does not illuminate the point adds nothing.
//
// ---- Subset rules: this file must stay valid GLSL 4.50 AND valid C++20 through GLM ----
//  1. No #version, no uniforms/in/out variables: the including program adds those. An include
//     guard (#ifndef) is fine in both languages. #include only of a sibling in shaders/common by
//     its bare name ("pbr.glsl"): the GL loader and the C++ compiler both look beside the file.
//  2. Float literals carry the f suffix (1.0f): a plain 1.0 is a double in C++ and breaks
//     GLM's template deduction (max(0.0, x) does not compile).
//  3. No swizzles at all (GLM_FORCE_XYZW_ONLY); use .x .y .z members and constructors.
//  4. Parameters are by value with no qualifier ("in" is allowed; C++ defines it away).
//     No out/inout parameters: return a struct instead (C++ cannot map "out T x" to "T& x").
//  5. Structs are built with constructor syntax in declaration order, LightSample(l, d, s):
//     a GLSL struct constructor and a C++20 parenthesised aggregate initialisation.
//  6. Only built-ins that GLM also provides (dot, length, clamp, min, max, abs, sqrt, pow,
//     inversesqrt, cross, floor, mix); declare every local with its type (no auto), no
//     recursion, no pointers, no C++ library calls.
//  7. Every function definition is prefixed with SHADING_FN (see below).
//  8. No GLSL built-in names for our functions (reflect, refract): overloading a built-in
//     with the same signature is an error in GLSL.
//  9. Every function returns a finite value for any finite input, including zero vectors,
//     huge vectors and grazing angles: guard divisions, square roots and pow.
#ifndef DIPTYCH_SHADING_GLSL
#define DIPTYCH_SHADING_GLSL

// Every function definition starts with SHADING_FN: nothing in GLSL, "inline" in C++ (the file
// is included from a header, so C++ needs inline definitions).
#ifndef SHADING_FN
#define SHADING_FN
#endif

// SHADING_ASSERT_UNIT(v): the unit-vector precondition of directTerm, checked where the language
// has an assert (engine/shading/shading.h: C++ debug builds); nothing in GLSL.
#ifndef SHADING_ASSERT_UNIT
#define SHADING_ASSERT_UNIT(v)
#endif

// Light types: the values of diptych::LightType (checked by a static_assert on the C++ side).
const int LIGHT_POINT = 0;
const int LIGHT_DIRECTIONAL = 1;
const int LIGHT_SPOT = 2;
const int LIGHT_QUAD_AREA = 3;
const int LIGHT_DISC_AREA = 4;
const int LIGHT_SPHERE_AREA = 5;

// Shading models (ShadingMaterial::model): the lecture's, and glTF 2.0 metallic-roughness
// (pbr.glsl). The values of diptych::ShadingModel.
const int SHADING_MODEL_LECTURE = 0;
const int SHADING_MODEL_GLTF = 1;

const float SHADING_FLT_MAX = 3.402823466e+38f;
const float SHADING_FLT_MIN = 1.175494351e-38f;  // 2^-126, the smallest normal float
const float SHADING_PI = 3.14159265358979f;

// A material with every texture already resolved at the point.
struct ShadingMaterial {
  vec3 color;          // C (linear RGB)
  float ka;            // ambient coefficient (scaled by each light's S_i, as in the lecture)
  float kd;            // diffuse coefficient
  float ks;            // glossy coefficient
  float exponent;      // e; < 0 is treated as 0, and 0^0 := 1
  vec3 specularColor;  // d_i
  float kps;           // perfect-mirror fraction
  vec3 mirrorColor;    // M_PS
  float kt;            // transmitted fraction
  vec3 transmitColor;  // M_T
  vec3 emission;       // M_E, radiance
  float ior;           // index of refraction of the inside
  float alpha;         // coverage
  // SHADING_MODEL_GLTF inputs (pbr.glsl); the lecture's fields above are then unused but for
  // emission, ior and alpha. Zero-initialised on the C++ side = the lecture model.
  int model;             // SHADING_MODEL_*
  vec3 baseColor;        // glTF baseColor (linear RGB), texture applied
  float metallic;        // [0, 1]
  float roughness;       // perceptual roughness [0, 1]; GGX alpha = roughness^2
  float transmission;    // KHR_materials_transmission factor
  float specularWeight;  // KHR_materials_specular "specular" (1 without the extension)
  vec3 specularTint;     // KHR_materials_specular "specularColor" (1 without the extension)
  // KHR_materials_iridescence (pbr.glsl pbrFilmFresnel), textures applied; 0 strength or 0
  // thickness: no film.
  float iridescence;           // strength [0, 1]
  float iridescenceIor;        // the film's index of refraction
  float iridescenceThickness;  // the film's thickness, nm
};

// One light, flattened from diptych::Light.
struct ShadingLight {
  int type;         // LIGHT_*
  vec3 color;       // linear RGB
  float intensity;  // cd (point, spot), lux (directional), radiance (area lights)
  vec3 position;    // world space
  vec3 direction;   // the direction the light travels (directional, spot, area normal)
  float range;      // > 0: hard cut-off distance; 0: infinite
  float cosInner;   // spot: cos(innerConeAngle)
  float cosOuter;   // spot: cos(outerConeAngle)
  float area;       // area lights: emitting area (sphere: projected area pi r^2)
};

// Direction and radiance of one light at one point.
struct LightSample {
  vec3 l;          // unit, toward the light; zero when undefined (point on the light)
  float distance;  // to the light's position; SHADING_FLT_MAX for directional lights
  vec3 radiance;   // S_i, finite, >= 0
};

// Factors of the reflection and transmission signals (secondaryTerms).
struct SecondaryWeights {
  vec3 reflection;
  vec3 transmission;
};

struct Refraction {
  vec3 t;                        // unit transmitted direction (mirror direction on TIR)
  bool totalInternalReflection;  // true: no transmitted ray exists
};

// Largest |component|; 0 for a zero vector, not finite for non-finite input.
SHADING_FN float maxAbsComponent(vec3 v) {
  return max(abs(v.x), max(abs(v.y), abs(v.z)));
}

// Unit vector along v, or the zero vector when v is zero or not finite. Scaling by the largest
// component first keeps dot(v, v) from overflowing for huge v or underflowing for tiny v.
SHADING_FN vec3 safeNormalize(vec3 v) {
  float m = maxAbsComponent(v);
  if (!(m > 0.0f) || !(m <= SHADING_FLT_MAX)) return vec3(0.0f);
  vec3 s = v / m;
  return s * inversesqrt(dot(s, s));
}

// |v| without overflow or underflow of the squares (saturates at SHADING_FLT_MAX).
SHADING_FN float safeLength(vec3 v) {
  float m = maxAbsComponent(v);
  if (!(m > 0.0f)) return 0.0f;
  if (!(m <= SHADING_FLT_MAX)) return SHADING_FLT_MAX;
  vec3 s = v / m;
  return min(m * sqrt(dot(s, s)), SHADING_FLT_MAX);
}

// |v| and v / |v| together, for sampleLight (per light and shading point: its divisions were the
// largest cost of the CPU shade loop, perf, issue 14). Where the largest component m is in
// [2^-60, 2^60] the squares neither overflow (3 * 2^120 < FLT_MAX) nor leave the normal range
// (2^-120 > FLT_MIN): |v| and v / |v| are formed directly, without the scaling's three divisions
// (within rounding of safeLength and safeNormalize, docs/ray-tracing.md "Shading model").
// Outside it, safeLength(v) and safeNormalize(v) bit for bit; a zero or non-finite v gives the
// zero direction.
struct LengthAndDirection {
  float magnitude;
  vec3 direction;
};
const float SHADING_UNSCALED_MIN = 8.67361738e-19f;  // 2^-60
const float SHADING_UNSCALED_MAX = 1.15292150e18f;   // 2^60
SHADING_FN LengthAndDirection safeLengthAndDirection(vec3 v) {
  float m = maxAbsComponent(v);
  if (!(m > 0.0f)) return LengthAndDirection(0.0f, vec3(0.0f));
  if (!(m <= SHADING_FLT_MAX)) return LengthAndDirection(SHADING_FLT_MAX, vec3(0.0f));
  if (m >= SHADING_UNSCALED_MIN && m <= SHADING_UNSCALED_MAX) {
    float vv = dot(v, v);
    return LengthAndDirection(sqrt(vv), v * inversesqrt(vv));
  }
  vec3 s = v / m;
  float ss = dot(s, s);
  return LengthAndDirection(min(m * sqrt(ss), SHADING_FLT_MAX), s * inversesqrt(ss));
}

// x clamped to [0, 1], with NaN mapped to 0 (GLSL leaves clamp(NaN) undefined).
SHADING_FN float saturate01(float x) {
  return x > 0.0f ? min(x, 1.0f) : 0.0f;
}

// base^e for the glossy lobe: negative bases count as 0, negative exponents as 0, 0^0 := 1
// (the limit of x^0), so pow never sees an argument with an undefined result.
// An integer e up to 1024 (the lecture's exponents are integers) is formed by repeated squaring
// (binary exponentiation, Knuth, TAOCP vol. 2, 4.6.3): at most 2 log2(e) products, each rounded
// once, so relative error <= (e - 1) 2^-24 against pow's ~1 ulp (docs/ray-tracing.md, "Shading
// model"); the same products in GLSL and C++. A result below FLT_MIN is returned as 0 (no
// subnormal products; pow would give the subnormal). Other exponents go to pow.
SHADING_FN float safePow(float base, float e) {
  float b = base > 0.0f ? base : 0.0f;
  float x = e > 0.0f ? e : 0.0f;
  if (x == 0.0f) return 1.0f;
  if (b == 0.0f) return 0.0f;
  if (x <= 1024.0f && x == floor(x)) {
    int k = int(x);
    float r = 1.0f;
    float p = min(b, SHADING_FLT_MAX);
    while (true) {
      if ((k & 1) != 0) r = r * p;
      k = k >> 1;
      if (k == 0) break;
      if (p < 1.08420217e-19f) return 0.0f;  // p < 2^-63: p^2 < FLT_MIN, a factor still to come
      p = min(p * p, SHADING_FLT_MAX);
    }
    // r * p can fall below FLT_MIN with both factors normal: GPUs flush that to 0, C++ would
    // keep a subnormal, so it is 0 on both sides.
    return r < SHADING_FLT_MIN ? 0.0f : min(r, SHADING_FLT_MAX);
  }
  return min(pow(b, x), SHADING_FLT_MAX);
}

// Mirror image of d about the line of n: 2 (n.d) n - d. With d pointing away from the surface
// the result does too (the lecture's r). Equals GLSL reflect(-d, n).
SHADING_FN vec3 reflectAbout(vec3 d, vec3 n) {
  return 2.0f * dot(n, d) * n - d;
}

// The lecture's refraction (Tema 5, "Cambio de dirección en la refracción"):
//   t = (r cos(theta_i) - cos(theta_t)) n - r i,  r = n_i / n_t,
//   cos(theta_t) = sqrt(1 - r^2 (1 - (i.n)^2)); total internal reflection when the radicand
//   would be negative, i.e. when sin^2(theta_t) = r^2 sin^2(theta_i) > 1.
// i: unit vector from the point toward where the light comes from (for a camera ray,
// i = -rayDirection); n: normal; eta = n_i / n_t (the caller knows which side is inside).
// n is flipped onto i's side if needed. sin^2 is formed before any square root; eta == 1
// returns -i exactly; on TIR the mirror direction is returned with the flag set.
SHADING_FN Refraction refractLecture(vec3 i, vec3 n, float eta) {
  vec3 I = safeNormalize(i);
  vec3 N = safeNormalize(n);
  float cosI = clamp(dot(I, N), -1.0f, 1.0f);
  if (cosI < 0.0f) {
    N = -N;
    cosI = -cosI;
  }
  if (eta == 1.0f || !(eta > 0.0f) || !(eta <= SHADING_FLT_MAX)) return Refraction(-I, false);
  // (1 - c)(1 + c) keeps sin^2 accurate near normal incidence, where 1 - c*c cancels.
  float sin2I = max(0.0f, (1.0f - cosI) * (1.0f + cosI));
  float sin2T = eta * eta * sin2I;
  if (sin2T > 1.0f) return Refraction(reflectAbout(I, N), true);
  float cosT = sqrt(1.0f - sin2T);
  return Refraction(safeNormalize((eta * cosI - cosT) * N - eta * I), false);
}

// Schlick's approximation of the Fresnel reflectance between media n1 and n2
// (C. Schlick, "An Inexpensive BRDF Model for Physically-based Rendering", 1994):
//   F = F0 + (1 - F0)(1 - cos)^5,  F0 = ((n1 - n2) / (n1 + n2))^2.
// cosTheta is the cosine on the optically thinner side (cos(theta_t) when leaving the denser
// medium); on total internal reflection use 1 for F.
SHADING_FN float fresnelSchlick(float cosTheta, float n1, float n2) {
  float sum = n1 + n2;
  float r0 = sum > 0.0f ? (n1 - n2) / sum : 0.0f;
  r0 = r0 * r0;
  float c = 1.0f - saturate01(cosTheta);
  float c2 = c * c;
  return r0 + (1.0f - r0) * c2 * c2 * c;
}

// Direction l and radiance S_i of a light at point p.
//   directional: l = -direction, S = color * intensity (lux)
//   point:       S = color * intensity / d^2 (cd / m^2)
//   spot:        point times the KHR_lights_punctual smooth cone factor
//                a = saturate(cd * scale + offset)^2, scale = 1 / max(0.001, cosInner -
//                cosOuter), offset = -cosOuter * scale, cd = dot(direction, -l)
//   area lights: for now a point at the centre with intensity radiance * area * cosine
//                (one-sided quad and disc, emitting along direction) or radiance * pi r^2
//                (sphere); stratified sampling of the surface comes later.
// range > 0 cuts the light off beyond that distance.
SHADING_FN LightSample sampleLight(ShadingLight light, vec3 p) {
  // Every product below is of finite, non-negative factors clamped to SHADING_FLT_MAX, so an
  // overflow saturates instead of becoming inf (or NaN through inf * 0).
  vec3 emitted = min(light.color * max(light.intensity, 0.0f), vec3(SHADING_FLT_MAX));
  emitted = max(emitted, vec3(0.0f));
  if (light.type == LIGHT_DIRECTIONAL) {
    vec3 ld = safeNormalize(-light.direction);
    return LightSample(ld, SHADING_FLT_MAX, maxAbsComponent(ld) > 0.0f ? emitted : vec3(0.0f));
  }
  LengthAndDirection toLight = safeLengthAndDirection(light.position - p);
  float d = toLight.magnitude;
  vec3 l = toLight.direction;
  if (!(d > 0.0f) || maxAbsComponent(l) == 0.0f) {
    return LightSample(vec3(0.0f), 0.0f, vec3(0.0f));
  }
  if (light.range > 0.0f && d > light.range) return LightSample(l, d, vec3(0.0f));
  float inv = 1.0f / d;
  float falloff = min(inv * inv, SHADING_FLT_MAX);  // inv * inv may overflow to inf
  // A point light has no axis: the cone cosine and the area are formed only for the lights that
  // use them (a point light's shading skipped a normalisation it never read; issue 14's profile).
  if (light.type == LIGHT_POINT) {
    return LightSample(l, d, min(emitted * falloff, vec3(SHADING_FLT_MAX)));
  }
  vec3 axis = safeNormalize(light.direction);
  float cosEmit = dot(axis, -l);  // cosine between the light's axis and the path to p
  float area = light.area > 0.0f ? min(light.area, SHADING_FLT_MAX) : 0.0f;  // NaN -> 0
  if (light.type == LIGHT_SPOT) {
    // The 0.001 floor is KHR_lights_punctual's own guard for inner == outer.
    float scale = 1.0f / max(0.001f, light.cosInner - light.cosOuter);
    float a = saturate01(cosEmit * scale - light.cosOuter * scale);
    falloff = falloff * a * a;
  } else if (light.type == LIGHT_QUAD_AREA || light.type == LIGHT_DISC_AREA) {
    falloff = min(falloff * area, SHADING_FLT_MAX) * saturate01(cosEmit);
  } else if (light.type == LIGHT_SPHERE_AREA) {
    falloff = min(falloff * area, SHADING_FLT_MAX);
  }
  vec3 s = min(emitted * falloff, vec3(SHADING_FLT_MAX));
  return LightSample(l, d, s);
}

// The lecture's DIRECTA: k_a C + k_d C max(0, n.l) + k_s d_i max(0, r.v)^e (see the header for
// the n.l > 0 gate on the glossy term).
// Precondition (issue 14): n, v, l are unit vectors (or zero: a zero l, sampleLight's "no
// direction", gives 0 for the terms that need it). Every caller already has them unit: the
// shading normal (makeSurfacePoint, the G-buffer), v = -(unit ray direction), l from sampleLight;
// re-normalising them here cost 12 divisions and 3 square roots per light and changed only the
// last bits (docs/ray-tracing.md, "Shading model"). SHADING_ASSERT_UNIT checks it in C++ debug
// builds.
SHADING_FN vec3 directTerm(ShadingMaterial m, vec3 n, vec3 v, vec3 l) {
  SHADING_ASSERT_UNIT(n);
  SHADING_ASSERT_UNIT(v);
  SHADING_ASSERT_UNIT(l);
  float nl = saturate01(dot(n, l));
  vec3 r = reflectAbout(l, n);
  float rv = saturate01(dot(r, v));
  // With k_s = 0 (the lecture's diffuse materials) the lobe's power is not formed: 0 times the
  // finite lobe (safePow saturates at FLT_MAX) is the same 0, and the repeated squaring was a
  // loop per light and hit for nothing (issue 14).
  float glossy = nl > 0.0f && m.ks != 0.0f ? safePow(rv, m.exponent) : 0.0f;
  return m.ka * m.color + m.kd * m.color * nl + m.ks * m.specularColor * glossy;
}

#include "pbr.glsl"

// The material's response to one light per unit of S_i: the lecture's DIRECTA or the glTF
// BRDF's pi f(l, v) max(0, n.l) (pbr.glsl), by m.model. n, v, l unit, as directTerm requires.
// The one place the model is chosen for direct light; the path tracer's next-event estimation
// calls it too.
SHADING_FN vec3 directResponse(ShadingMaterial m, vec3 n, vec3 v, vec3 l) {
  if (m.model == SHADING_MODEL_GLTF) return pbrDirect(m, n, v, l);
  return directTerm(m, n, v, l);
}

// One summand of the lecture's sum, V_i S_i L_dir,i, given the response L_dir,i already formed
// (the Whitted tracer forms it first, to trace shadow rays only where it is not zero).
SHADING_FN vec3 lightContributionOf(vec3 response, LightSample s, float visibility) {
  vec3 lit = saturate01(visibility) * s.radiance * response;
  return min(lit, vec3(SHADING_FLT_MAX));  // S_i near FLT_MAX times a factor > 1 saturates
}

// One summand of the lecture's sum: V_i S_i L_dir,i (L_dir,i by the material's model).
SHADING_FN vec3 lightContribution(ShadingMaterial m, vec3 n, vec3 v, LightSample s,
                                  float visibility) {
  return lightContributionOf(directResponse(m, n, v, s.l), s, visibility);
}

// M_E + A_G: the terms that do not depend on any light (the same in both models: A_G is the
// lecture's global ambient radiance, added as it is).
SHADING_FN vec3 emittedAndAmbient(ShadingMaterial m, vec3 ambientGlobal) {
  return m.emission + ambientGlobal;
}

// The factors of the reflected and transmitted radiance: the lecture's k_ps M_PS and k_t M_T,
// or the glTF model's Fresnel-weighted ones (pbrSecondaryWeights). n, v as for lightContribution.
SHADING_FN SecondaryWeights secondaryWeights(ShadingMaterial m, vec3 n, vec3 v) {
  if (m.model == SHADING_MODEL_GLTF) return pbrSecondaryWeights(m, n, v);
  return SecondaryWeights(m.kps * m.mirrorColor, m.kt * m.transmitColor);
}

// k_ps M_PS L_refl + k_t M_T L_trans (lecture), given the radiance arriving along the mirror
// direction and the refracted one; the glTF model weights them by its own terms.
SHADING_FN vec3 secondaryTerms(ShadingMaterial m, vec3 n, vec3 v, vec3 reflected,
                               vec3 transmitted) {
  SecondaryWeights w = secondaryWeights(m, n, v);
  return min(w.reflection * reflected + w.transmission * transmitted, vec3(SHADING_FLT_MAX));
}

// Beer-Lambert transmittance of KHR_materials_volume over a path of length d inside the medium:
// T = c^(d / d_a) per channel, i.e. exp(-sigma d) with sigma = -ln(c) / d_a (c the attenuation
// colour reached after the attenuation distance d_a). 1 when d_a <= 0 (no attenuation) or d <= 0.
SHADING_FN vec3 volumeTransmittance(vec3 attenuationColor, float attenuationDistance, float d) {
  if (!(attenuationDistance > 0.0f) || !(d > 0.0f)) return vec3(1.0f);
  vec3 c = clamp(attenuationColor, vec3(0.0f), vec3(1.0f));
  float x = min(d / attenuationDistance, SHADING_FLT_MAX);
  return vec3(pow(c.x, x), pow(c.y, x), pow(c.z, x));
}

// Whether the reflection / transmission signal has a weight for this material, by its own model:
// the gate of every producer and of Whitted (docs/materials.md). Lecture: k_ps > 0, k_t > 0;
// glTF: pbrHasReflection / pbrHasTransmission. `lobe`: the producer writes the specular lobe's
// prefiltered radiance (env_* prefiltered), which rough glTF lobes also want.
SHADING_FN bool hasReflection(ShadingMaterial m, bool lobe) {
  if (m.model == SHADING_MODEL_GLTF) return pbrHasReflection(m, lobe);
  return m.kps > 0.0f;
}
SHADING_FN bool hasTransmission(ShadingMaterial m) {
  if (m.model == SHADING_MODEL_GLTF) return pbrHasTransmission(m);
  return m.kt > 0.0f;
}

// The texture_filtering slot's signal (docs/textures.md): the colour the material's model reads,
// with the colour texture applied through the producer's filter, and the coverage. The lecture's
// model reads C (colour x texel); glTF's reads the base colour (baseColorFactor x texel) and
// derives its diffuse and metal F0 from it (pbr.glsl), so that is what its signal holds: C of a
// metal is 0 (gltfDiffuseColor), and a signal of C turned textured metals black. (Lecture-model
// materials re-mapped per texel from glTF inputs also carry the base colour: the producers and
// shade decide that from the material, remapsPerTexel, which this struct does not record.)
SHADING_FN vec3 textureSignalColor(ShadingMaterial m) {
  if (m.model == SHADING_MODEL_GLTF) return m.baseColor;
  return m.color;
}
// The material with the signal's colour and coverage in place of its own lookup's (shade).
SHADING_FN ShadingMaterial withTextureSignal(ShadingMaterial m, vec3 color, float alpha) {
  if (m.model != SHADING_MODEL_GLTF) m.color = color;
  m.baseColor = color;
  m.alpha = alpha;
  return m;
}

// The reflection signal's alpha says what it holds: 1 radiance along the mirror direction
// (weighted by secondaryWeights), 2 the GGX lobe's prefiltered radiance (env_* with prefiltered
// levels), which a glTF material weights by the lobe's albedo without the roughness fade (the
// split sum, Karis 2013). The lecture model has no lobe: alpha 2 never reaches it.
SHADING_FN vec3 secondaryTermsOf(ShadingMaterial m, vec3 n, vec3 v, vec3 reflected,
                                 float reflectedAlpha, vec3 transmitted) {
  SecondaryWeights w = secondaryWeights(m, n, v);
  if (reflectedAlpha > 1.5f && m.model == SHADING_MODEL_GLTF)
    w.reflection = pbrLobeReflectionWeight(m, n, v);
  return min(w.reflection * reflected + w.transmission * transmitted, vec3(SHADING_FLT_MAX));
}

#endif  // DIPTYCH_SHADING_GLSL
