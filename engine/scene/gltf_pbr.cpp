#include "engine/scene/gltf_pbr.h"

#include <algorithm>
#include <cmath>

namespace diptych {
namespace {
// Rec. 709 luminance, used to collapse an RGB reflectance into the scalar k_s / k_ps.
float luminance(const vec3& c) {
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}
}  // namespace

LectureCoefficients gltfPbrToLecture(vec3 base, float metallic, float roughness, float transmission,
                                     float ior) {
  metallic = std::clamp(metallic, 0.f, 1.f);
  roughness = std::clamp(roughness, 0.f, 1.f);
  transmission = std::clamp(transmission, 0.f, 1.f);
  LectureCoefficients m;
  // Dielectric reflectance at normal incidence from the IOR, F0 = ((n-1)/(n+1))^2 (0.04 for the
  // default 1.5); metals reflect their base colour (glTF spec appendix B).
  const float dielectricF0 = std::pow((ior - 1.f) / (ior + 1.f), 2.f);
  const vec3 f0 = glm::mix(vec3(dielectricF0), base, metallic);
  // Diffuse: metals have none, and transmission replaces diffuse (the glTF dielectric BRDF is
  // mix(diffuse, transmission, transmissionFactor)).
  m.color = gltfDiffuseColor(base, metallic);
  m.kd = 1.f - transmission;
  m.ks = luminance(f0);
  m.specularColor = m.ks > 0.f ? f0 / m.ks : vec3(1.f);
  // Blinn-Phong exponent equivalent to a Beckmann/GGX lobe of width alpha = roughness^2:
  // e = 2/alpha^2 - 2 (Walter et al. 2007, eq. 30). alpha is clamped to 0.01 so a perfectly
  // smooth surface gets e = 19998 rather than infinity.
  const float alpha = std::max(roughness * roughness, 0.01f);
  m.exponent = std::max(2.f / (alpha * alpha) - 2.f, 1.f);
  // Mirror fraction: the normal-incidence reflectance, fading out as roughness blurs the mirror.
  m.kps = m.ks * (1.f - roughness);
  m.mirrorColor = m.specularColor;
  m.kt = transmission * (1.f - metallic);
  m.transmitColor = base;  // glTF transmission is tinted by the base colour
  return m;
}

void lectureToGltfPbr(Material& m) {
  const float kd = std::max(m.kd, 0.f), kps = std::max(m.kps, 0.f), kt = std::max(m.kt, 0.f);
  const float metallic = kps + kd > 0.f ? kps / (kps + kd) : 0.f;
  vec3 base = glm::mix(kd * m.color, kps * m.mirrorColor, metallic);
  if (kt > 0.f) base = glm::mix(base, m.transmitColor, kt / (kt + kd));
  // e = 2 / alpha^2 - 2 inverted (Walter et al. 2007, eq. 30, as gltfPbrToLecture), roughness =
  // sqrt(alpha); a lecture mirror is a smooth lobe, a material with no glossy term fully rough.
  const float alpha = std::sqrt(2.f / (std::max(m.exponent, 0.f) + 2.f));
  const float roughness = kps > 0.f ? 0.f : m.ks > 0.f ? std::sqrt(alpha) : 1.f;
  m.baseColorFactor = vec4(glm::clamp(base, vec3(0.f), vec3(1.f)), m.alpha);
  m.metallicFactor = metallic;
  m.roughnessFactor = roughness;
  m.transmissionFactor = std::clamp(kt, 0.f, 1.f);
}

std::optional<ShadingModel> parseShadingModel(const std::string& name) {
  if (name == "lecture") return ShadingModel::Lecture;
  if (name == "gltf") return ShadingModel::Gltf;
  return std::nullopt;
}

void forceShadingModel(Scene& scene, ShadingModel model) {
  for (Material& m : scene.materials) {
    if (model == ShadingModel::Gltf && m.model != ShadingModel::Gltf) lectureToGltfPbr(m);
    m.model = model;
  }
}

}  // namespace diptych
