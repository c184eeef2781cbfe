// pbr.glsl: the glTF 2.0 metallic-roughness BRDF (glTF 2.0 specification, Appendix B "BRDF
// Implementation"), with KHR_materials_ior, KHR_materials_specular and
// KHR_materials_transmission, written once for GLSL 4.50 and C++ under the subset rules at the
// top of shading.glsl, which includes this file after ShadingMaterial and its helpers.
//
//   f = mix(dielectric, metal, metallic)
//   metal      = F(base) D V                                     conductor Fresnel
//   dielectric = (1 - w max(F_d)) c_diff / pi + w F_d D V        KHR_materials_specular fresnel_mix
//   c_diff     = base (1 - transmission)                         transmission replaces diffuse
//   F(f0)      = f0 + (1 - f0) (1 - |v.h|)^5                      Schlick
//   F_d        = F(min(((ior - 1) / (ior + 1))^2 specularTint, 1)), w = specularWeight
//   D          = a^2 / (pi ((n.h)^2 (a^2 - 1) + 1)^2)             GGX / Trowbridge-Reitz, a = r^2
//   V          = 0.5 / (n.l sqrt((n.v)^2 (1 - a^2) + a^2) + n.v sqrt((n.l)^2 (1 - a^2) + a^2))
//                                                               Smith height-correlated G / (4 n.l n.v)
// KHR_materials_iridescence: both lobes' F become mix(F, F_film, iridescence) with the same f0
// (base for the metal, F_d's f0 for the dielectric), F_film the thin-film Fresnel below.
// Units: the lecture's S_i is the radiance a white Lambertian surface facing the light reflects,
// E / pi (docs/materials.md), so one light contributes f E n.l = pi f n.l S_i: pbrDirect returns
// pi f n.l, which for a white diffuse surface is n.l, the lecture's k_d C n.l with k_d C = 1.
// The transmission BTDF is a delta here (the transmission signal, traced along refractLecture):
// lights are not seen through a rough transmissive surface. KHR_materials_volume attenuates
// inside the medium (volumeTransmittance in shading.glsl), applied by the tracers and the
// raster blend producers, not by this BRDF.
#ifndef DIPTYCH_PBR_GLSL
#define DIPTYCH_PBR_GLSL

#include "env_brdf_table.glsl"

// GGX alpha = roughness^2 (glTF Appendix B), floored at 1e-3 so that D and V stay finite at
// roughness 0 (D's peak is then 1 / (pi 1e-6), a near-mirror). Filament floors likewise.
SHADING_FN float pbrAlpha(float roughness) {
  float r = saturate01(roughness);
  return max(r * r, 1.0e-3f);
}

// (1 - c)^5 for Schlick's Fresnel, c clamped to [0, 1].
SHADING_FN float pbrSchlickWeight(float c) {
  float x = 1.0f - saturate01(c);
  float x2 = x * x;
  return x2 * x2 * x;
}

// Dielectric reflectance at normal incidence: ((ior - 1) / (ior + 1))^2 (KHR_materials_ior; 0.04
// at 1.5) tinted by specularColor and clamped to 1 (KHR_materials_specular).
SHADING_FN vec3 pbrDielectricF0(ShadingMaterial m) {
  float sum = m.ior + 1.0f;
  float r = sum > 0.0f ? (m.ior - 1.0f) / sum : 0.0f;
  r = min(r * r, 1.0f);
  return min(r * max(m.specularTint, vec3(0.0f)), vec3(1.0f));
}

// ---- KHR_materials_iridescence: the thin-film Fresnel F_film ----
// Belcour & Barla 2017, "A Practical Extension to Microfacet Theory for the Modeling of Varying
// Iridescence", in the approximate form of the KHR_materials_iridescence spec's implementation
// notes: Schlick at both interfaces (no polarisation), reflection phase shifts of 0 or pi, and
// the Airy sum's orders m = 0, 1, 2 integrated over the spectrum in Fourier space against the
// Gaussian fits of the CIE XYZ sensitivities, then XYZ -> linear sRGB. The film sits under air
// (no clearcoat here). docs/materials.md gives the limits.

// Normal-incidence reflectance of the interface from IOR n1 into n2: ((n2 - n1) / (n2 + n1))^2.
SHADING_FN float pbrIorToF0(float n2, float n1) {
  float sum = n2 + n1;
  float r = sum > 0.0f ? (n2 - n1) / sum : 0.0f;
  return r * r;
}

// The IOR (under air) whose normal-incidence reflectance is f0, n = (1 + sqrt f0) / (1 - sqrt f0),
// for dielectrics and metals alike (the spec: a metal's extinction is taken as 0). f0 + 1e-4 as
// the spec writes it, kept below 1 so that n stays finite.
SHADING_FN vec3 pbrF0ToIor(vec3 f0) {
  vec3 s = sqrt(clamp(f0 + vec3(1.0e-4f), vec3(0.0f), vec3(0.9999f)));
  return (vec3(1.0f) + s) / (vec3(1.0f) - s);
}

// The spectral sensitivity of one Airy order with optical path difference opd (nm) and phase
// shift `shift`, as linear sRGB: the spec's Gaussian fits of the XYZ matching functions
// (value, mean, variance per channel, a second lobe for X) in Fourier space at 2 pi opd, each
// scaled so that Y integrates to 1 (1.0685e-7), then the XYZ -> Rec. 709 matrix (D65).
SHADING_FN vec3 pbrFilmSensitivity(float opd, vec3 shift) {
  float phase = 2.0f * SHADING_PI * opd * 1.0e-9f;
  vec3 val = vec3(5.4856e-13f, 4.4201e-13f, 5.2481e-13f);
  vec3 pos = vec3(1.6810e+06f, 1.7953e+06f, 2.2084e+06f);
  vec3 var = vec3(4.3278e+09f, 9.3046e+09f, 6.6121e+09f);
  vec3 xyz = val * sqrt(2.0f * SHADING_PI * var) * cos(pos * phase + shift) *
             exp(-(phase * phase) * var);
  xyz.x += 9.7470e-14f * sqrt(2.0f * SHADING_PI * 4.5282e+09f) * cos(2.2399e+06f * phase + shift.x) *
           exp(-4.5282e+09f * (phase * phase));
  xyz = xyz / 1.0685e-7f;
  return vec3(3.2404542f * xyz.x - 1.5371385f * xyz.y - 0.4985314f * xyz.z,
              -0.9692660f * xyz.x + 1.8760108f * xyz.y + 0.0415560f * xyz.z,
              0.0556434f * xyz.x - 0.2040259f * xyz.y + 1.0572252f * xyz.z);
}

// F_film: the reflectance of a film of IOR filmIor (clamped to >= 1, the schema's minimum) and
// `thickness` nm over a base of normal-incidence reflectance baseF0, at cos(theta1) of the
// incident direction and the (micro)normal. Without a film (thickness <= 0) exactly Schlick's
// F(baseF0): the spec's "a zero-thickness film has no effect".
SHADING_FN vec3 pbrFilmFresnel(float filmIor, vec3 baseF0, float thickness, float cosTheta1) {
  float c1 = saturate01(cosTheta1);
  if (!(thickness > 0.0f)) return baseF0 + (vec3(1.0f) - baseF0) * pbrSchlickWeight(c1);
  float n2 = max(filmIor, 1.0f);
  // Snell into the film (n2 >= 1: no total internal reflection): cos theta2.
  float sin2Sq = (1.0f - c1 * c1) / (n2 * n2);
  float c2 = sqrt(max(1.0f - sin2Sq, 0.0f));
  // First interface, air -> film: R12 = R21 by Schlick at theta1, T121 = 1 - R12.
  float r0 = pbrIorToF0(n2, 1.0f);
  float r12 = r0 + (1.0f - r0) * pbrSchlickWeight(c1);
  float t121 = 1.0f - r12;
  // Second interface, film -> base: the base's IOR from its F0, Schlick at theta2.
  vec3 n3 = pbrF0ToIor(baseF0);
  vec3 r1 = vec3(pbrIorToF0(n3.x, n2), pbrIorToF0(n3.y, n2), pbrIorToF0(n3.z, n2));
  vec3 r23 = r1 + (vec3(1.0f) - r1) * pbrSchlickWeight(c2);
  // Phase shifts: pi on reflection off a lower IOR. phi12 = 0 (n2 >= 1), so phi21 = pi;
  // phi23 = pi where the base's IOR is below the film's.
  vec3 phi = vec3(SHADING_PI) + vec3(n3.x < n2 ? SHADING_PI : 0.0f, n3.y < n2 ? SHADING_PI : 0.0f,
                                     n3.z < n2 ? SHADING_PI : 0.0f);
  // Optical path difference of one round trip in the film, 2 n2 d cos(theta2) (Belcour & Barla
  // 2017, Sec. 3; the spec's text writes cos theta1 there, its reference code cos theta2).
  // Capped at 1e5 nm, where every sensitivity term has long underflowed to 0 (exp(-phase^2 var)
  // is 0 in float from about 2.5e4 nm): absurd thicknesses or IORs would overflow it to inf, and
  // cos(inf) exp(-inf) is NaN.
  float opd = min(2.0f * n2 * thickness * c2, 1.0e5f);
  // Airy sum: I = C0 + sum_{m=1,2} C_m S_m, C0 = R12 + Rs, C_m = (Rs - T121) r123^m,
  // Rs = T121^2 R23 / (1 - R12 R23), r123 = sqrt(R12 R23) clamped away from 0 and 1.
  vec3 r123Sq = clamp(r12 * r23, vec3(1.0e-5f), vec3(0.9999f));
  vec3 r123 = sqrt(r123Sq);
  vec3 rs = (t121 * t121) * r23 / (vec3(1.0f) - r123Sq);
  vec3 cm = (rs - vec3(t121)) * r123;
  vec3 i = vec3(r12) + rs + cm * (2.0f * pbrFilmSensitivity(opd, phi));
  cm = cm * r123;
  i = i + cm * (2.0f * pbrFilmSensitivity(2.0f * opd, 2.0f * phi));
  // The spec floors I at 0; the approximations (Schlick, the Gaussian fits, the matrix's negative
  // lobes) can also overshoot 1, which would make the dielectric's 1 - w max(F) negative: a
  // reflectance is clamped to [0, 1].
  return clamp(i, vec3(0.0f), vec3(1.0f));
}

// Whether the material has a film: a strength and a thickness above 0. Without one every
// function here takes its film-free path, unchanged.
SHADING_FN bool pbrHasFilm(ShadingMaterial m) {
  return m.iridescence > 0.0f && m.iridescenceThickness > 0.0f;
}

// mix(F, F_film, iridescence) for Schlick's F = fSchlick of the same f0, at cos(theta1) = c.
SHADING_FN vec3 pbrFilmMix(ShadingMaterial m, vec3 fSchlick, vec3 f0, float c) {
  vec3 film = pbrFilmFresnel(m.iridescenceIor, f0, m.iridescenceThickness, c);
  return mix(fSchlick, film, saturate01(m.iridescence));
}

// GGX normal distribution D(n.h).
SHADING_FN float pbrD(float nh, float a) {
  float a2 = a * a;
  float c = saturate01(nh);
  float d = c * c * (a2 - 1.0f) + 1.0f;  // >= a2 > 0 for c in [0, 1]
  return a2 / (SHADING_PI * d * d);
}

// Smith height-correlated visibility V = G2 / (4 n.l n.v) (Heitz 2014, eq. 99).
SHADING_FN float pbrV(float nl, float nv, float a) {
  float a2 = a * a;
  float gv = nl * sqrt(max(nv * nv * (1.0f - a2) + a2, 0.0f));
  float gl = nv * sqrt(max(nl * nl * (1.0f - a2) + a2, 0.0f));
  float s = gv + gl;
  return s > 0.0f ? 0.5f / s : 0.0f;
}

// pi f(l, v) max(0, n.l): the glTF BRDF's response to one light per unit of S_i. n, v, l need
// not be normalised; 0 for a light below the tangent plane. n.v is floored at 1e-4 (as the
// glTF sample viewer clamps it) so that a normal-mapped normal facing away from v stays finite.
SHADING_FN vec3 pbrDirect(ShadingMaterial m, vec3 n, vec3 v, vec3 l) {
  vec3 N = safeNormalize(n);
  vec3 V = safeNormalize(v);
  vec3 L = safeNormalize(l);
  float nl = dot(N, L);
  if (!(nl > 0.0f)) return vec3(0.0f);
  nl = min(nl, 1.0f);
  float nv = clamp(dot(N, V), 1.0e-4f, 1.0f);
  vec3 H = safeNormalize(L + V);
  float vh = saturate01(dot(V, H));
  float a = pbrAlpha(m.roughness);
  float specular = pbrD(dot(N, H), a) * pbrV(nl, nv, a);
  float fw = pbrSchlickWeight(vh);
  vec3 base = clamp(m.baseColor, vec3(0.0f), vec3(1.0f));
  vec3 fMetal = base + (vec3(1.0f) - base) * fw;
  vec3 f0 = pbrDielectricF0(m);
  vec3 fDielectric = f0 + (vec3(1.0f) - f0) * fw;
  if (pbrHasFilm(m)) {  // F at the microfacet normal h: cos(theta1) = v.h
    fMetal = pbrFilmMix(m, fMetal, base, vh);
    fDielectric = pbrFilmMix(m, fDielectric, f0, vh);
  }
  float w = saturate01(m.specularWeight);
  float fMax = max(fDielectric.x, max(fDielectric.y, fDielectric.z));
  vec3 diffuse = base * ((1.0f - saturate01(m.transmission)) / SHADING_PI);
  vec3 dielectric = (1.0f - w * fMax) * diffuse + w * fDielectric * specular;
  vec3 f = mix(dielectric, fMetal * specular, saturate01(m.metallic));
  return min(f * (SHADING_PI * nl), vec3(SHADING_FLT_MAX));
}

// Directional albedo of the GGX lobe with Schlick Fresnel, E(n.v) = f0 A + B (Karis 2013, "Real
// Shading in Unreal Engine 4", split sum's second factor). Returns (A, B), bilinear in the table
// env_brdf_table.glsl, which engine/shading/env_brdf.cpp integrates from THIS file's pbrV and
// pbrSchlickWeight (importance sampling the GGX D). Nodes at n.v = x^2, x = i / (N - 1): the
// lookup coordinate is sqrt(n.v). The same code runs in GLSL and C++; docs/materials-secondary.md
// gives the table's size, sample count and interpolation error.
SHADING_FN vec2 pbrEnvironmentBrdfNode(int i, int j) {
  int k = 2 * (j * ENV_BRDF_SIZE + i);
  return vec2(ENV_BRDF_TABLE[k], ENV_BRDF_TABLE[k + 1]);
}
SHADING_FN vec2 pbrEnvironmentBrdf(float nv, float roughness) {
  float last = float(ENV_BRDF_SIZE - 1);
  float x = sqrt(saturate01(nv)) * last;
  float y = saturate01(roughness) * last;
  int i = min(int(x), ENV_BRDF_SIZE - 2);
  int j = min(int(y), ENV_BRDF_SIZE - 2);
  float fx = x - float(i);
  float fy = y - float(j);
  vec2 lower = mix(pbrEnvironmentBrdfNode(i, j), pbrEnvironmentBrdfNode(i + 1, j), fx);
  vec2 upper = mix(pbrEnvironmentBrdfNode(i, j + 1), pbrEnvironmentBrdfNode(i + 1, j + 1), fx);
  return mix(lower, upper, fy);
}

// The specular lobe's Fresnel-weighted directional albedo, mix(w E(f0_d), E(base), metallic) with
// E = f0 A + B from pbrEnvironmentBrdf: the split sum's second factor (Karis 2013). It weights a
// reflection signal that is already the lobe's prefiltered radiance (env_* with prefiltered
// levels, docs/environment-maps.md), for which no roughness fade applies.
SHADING_FN vec3 pbrLobeReflectionWeight(ShadingMaterial m, vec3 n, vec3 v) {
  float nv = clamp(dot(safeNormalize(n), safeNormalize(v)), 1.0e-4f, 1.0f);
  vec2 ab = pbrEnvironmentBrdf(nv, m.roughness);
  vec3 base = clamp(m.baseColor, vec3(0.0f), vec3(1.0f));
  vec3 f0 = pbrDielectricF0(m);
  float w = saturate01(m.specularWeight);
  vec3 albedo = mix(w * (f0 * ab.x + vec3(ab.y)), base * ab.x + vec3(ab.y), saturate01(m.metallic));
  if (pbrHasFilm(m)) {
    // The film's F is taken at n.v, constant over the lobe, where E(F) = F (A + B) exactly (the
    // split sum with a constant F); mixed with the Schlick E by the strength, as F is.
    float k = saturate01(m.iridescence);
    float lobe = ab.x + ab.y;
    vec3 dielectric = mix(f0 * ab.x + vec3(ab.y),
                          pbrFilmFresnel(m.iridescenceIor, f0, m.iridescenceThickness, nv) * lobe, k);
    vec3 metal = mix(base * ab.x + vec3(ab.y),
                     pbrFilmFresnel(m.iridescenceIor, base, m.iridescenceThickness, nv) * lobe, k);
    albedo = mix(w * dielectric, metal, saturate01(m.metallic));
  }
  return clamp(albedo, vec3(0.0f), vec3(1.0f));
}

// Factors of the reflection signal (radiance along the mirror direction of v) and of the
// transmission signal (along the refracted direction):
//   reflection   = (1 - roughness) pbrLobeReflectionWeight: the Fresnel-weighted albedo of the
//                  specular lobe, fading out with roughness as the lecture mapping's k_ps does
//                  (a mirror ray stands for a sharp lobe only; a rough lobe's environment light
//                  is left out, not smeared, unless the signal is prefiltered: secondaryTermsOf);
//   transmission = (1 - metallic) transmission (1 - w max(F_d(n.v))) base: what the dielectric's
//                  Fresnel layer lets through, tinted by the base colour (KHR_materials_transmission).
SHADING_FN SecondaryWeights pbrSecondaryWeights(ShadingMaterial m, vec3 n, vec3 v) {
  float nv = clamp(dot(safeNormalize(n), safeNormalize(v)), 1.0e-4f, 1.0f);
  vec3 reflection = (1.0f - saturate01(m.roughness)) * pbrLobeReflectionWeight(m, n, v);
  vec3 f0 = pbrDielectricF0(m);
  float w = saturate01(m.specularWeight);
  float metallic = saturate01(m.metallic);
  vec3 base = clamp(m.baseColor, vec3(0.0f), vec3(1.0f));
  vec3 fd = f0 + (vec3(1.0f) - f0) * pbrSchlickWeight(nv);
  if (pbrHasFilm(m)) fd = pbrFilmMix(m, fd, f0, nv);
  float fMax = max(fd.x, max(fd.y, fd.z));
  vec3 transmission = ((1.0f - metallic) * saturate01(m.transmission) * (1.0f - w * fMax)) * base;
  return SecondaryWeights(reflection, transmission);
}

// Whether the glTF model gives the reflection signal a weight: a specular lobe exists (a metal, or
// a dielectric with specularWeight > 0: Schlick's Fresnel reaches 1 at grazing even at f0 = 0)
// and a mirror ray stands for it (roughness < 1), or, for a prefiltered lobe signal, at any
// roughness. The transmission signal: (1 - metallic) transmission > 0 and a base colour.
SHADING_FN bool pbrHasReflection(ShadingMaterial m, bool lobe) {
  bool specular = saturate01(m.metallic) > 0.0f || saturate01(m.specularWeight) > 0.0f;
  return specular && (lobe || saturate01(m.roughness) < 1.0f);
}
SHADING_FN bool pbrHasTransmission(ShadingMaterial m) {
  vec3 base = clamp(m.baseColor, vec3(0.0f), vec3(1.0f));
  return (1.0f - saturate01(m.metallic)) * saturate01(m.transmission) > 0.0f &&
         max(base.x, max(base.y, base.z)) > 0.0f;
}

#endif  // DIPTYCH_PBR_GLSL
