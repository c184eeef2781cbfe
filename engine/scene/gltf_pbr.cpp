#include "engine/scene/gltf_pbr.h"

#include <algorithm>
#include <cmath>

namespace diptych {

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
