// gltf_lecture.glsl: glTF metallic-roughness parameters mapped onto the lecture's coefficients
// (docs/scene-format.md, "glTF material mapping"; docs/materials.md), written once for GLSL 4.50
// and C++ under the subset rules at the top of shading.glsl. It needs nothing from that file, so
// the scene layer compiles it alone (engine/scene/gltf_pbr.h: the loaders' constants and the CPU
// surface code per texel) and the GL scene code includes it (gl/scene_shading.glsl: the same
// coefficients per texel, and gl_shade.frag's base-colour signal).
#ifndef DIPTYCH_GLTF_LECTURE_GLSL
#define DIPTYCH_GLTF_LECTURE_GLSL

#ifndef SHADING_FN
#define SHADING_FN
#endif

// The lecture coefficients a glTF material maps to: C, k_d, k_s, e, d_i, k_ps, M_PS, k_t, M_T.
struct LectureCoefficients {
  vec3 color;
  float kd;
  float ks;
  float exponent;
  vec3 specularColor;
  float kps;
  vec3 mirrorColor;
  float kt;
  vec3 transmitColor;
};

// Rec. 709 luminance, which collapses an RGB reflectance into the scalar k_s / k_ps.
SHADING_FN float gltfLuminance(vec3 c) {
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

// The diffuse colour C = base (1 - metallic), metallic clamped to [0, 1]: metals have no diffuse
// term (glTF spec appendix B).
SHADING_FN vec3 gltfDiffuseColor(vec3 base, float metallic) {
  return base * (1.0f - clamp(metallic, 0.0f, 1.0f));
}

// base: linear base colour (alpha ignored); metallic, roughness, transmission in [0, 1] (clamped
// here); ior of the dielectric.
SHADING_FN LectureCoefficients gltfPbrToLecture(vec3 base, float metallic, float roughness,
                                                float transmission, float ior) {
  metallic = clamp(metallic, 0.0f, 1.0f);
  roughness = clamp(roughness, 0.0f, 1.0f);
  transmission = clamp(transmission, 0.0f, 1.0f);
  // Dielectric reflectance at normal incidence from the IOR, F0 = ((n-1)/(n+1))^2 (0.04 for the
  // default 1.5); metals reflect their base colour (glTF spec appendix B). Squared by a product:
  // GLSL's pow is undefined for a negative base, and (n-1)/(n+1) is negative for an IOR below 1
  // (which validation accepts).
  float f = (ior - 1.0f) / (ior + 1.0f);
  float dielectricF0 = f * f;
  vec3 f0 = mix(vec3(dielectricF0), base, metallic);
  float ks = gltfLuminance(f0);
  vec3 specularColor = ks > 0.0f ? f0 / ks : vec3(1.0f);
  // Blinn-Phong exponent equivalent to a Beckmann/GGX lobe of width alpha = roughness^2:
  // e = 2/alpha^2 - 2 (Walter et al. 2007, eq. 30). alpha is clamped to 0.01 so a perfectly
  // smooth surface gets e = 19998 rather than infinity.
  float alpha = max(roughness * roughness, 0.01f);
  // Diffuse: metals have none, and transmission replaces diffuse (the glTF dielectric BRDF is
  // mix(diffuse, transmission, transmissionFactor)). Mirror fraction: the normal-incidence
  // reflectance, fading out as roughness blurs the mirror. glTF transmission is tinted by the
  // base colour. Built member by member, not with shading.glsl's constructor syntax (its rule 5):
  // the loaders compile this file under the fuzz preset too, and clang 14 (Debian 12's) has no
  // parenthesised aggregate initialisation.
  LectureCoefficients c;
  c.color = gltfDiffuseColor(base, metallic);
  c.kd = 1.0f - transmission;
  c.ks = ks;
  c.exponent = max(2.0f / (alpha * alpha) - 2.0f, 1.0f);
  c.specularColor = specularColor;
  c.kps = ks * (1.0f - roughness);
  c.mirrorColor = specularColor;
  c.kt = transmission * (1.0f - metallic);
  c.transmitColor = base;
  return c;
}

#endif
