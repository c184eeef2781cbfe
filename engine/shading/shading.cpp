#include "engine/shading/shading.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "engine/scene/gltf_pbr.h"

namespace diptych::shading {

ShadingLight toShadingLight(const Light& light) {
  float area = 0.f;
  switch (light.type) {
    case LightType::QuadArea:
      area = glm::length(glm::cross(light.edgeU, light.edgeV));
      break;
    case LightType::DiscArea:
    case LightType::SphereArea:  // projected area of the sphere, seen from any direction
      area = std::numbers::pi_v<float> * light.radius * light.radius;
      break;
    default:
      break;
  }
  return ShadingLight(int(light.type), light.color, light.intensity, light.position,
                      light.direction, light.range, std::cos(light.innerConeAngle),
                      std::cos(light.outerConeAngle), area);
}

bool materialHasReflection(const Material& m, bool lobe) {
  ShadingMaterial s = toShadingMaterial(m);
  if (m.metallicRoughnessTexture >= 0) s.roughness = 0.f;
  if (hasReflection(s, lobe)) return true;
  // A checker replaces a re-mapped material's base colour (remapsPerTexel) instead of scaling
  // baseColorFactor down: its lecture coefficients at a texel are those of one of its two
  // colours, which the loader's constants (from baseColorFactor) do not bound.
  if (!m.checker || !remapsPerTexel(m)) return false;
  const float roughness = m.metallicRoughnessTexture >= 0 ? 0.f : m.roughnessFactor;
  for (const vec3& colour : {m.checker->colorA, m.checker->colorB}) {
    const LectureCoefficients k =
        gltfPbrToLecture(colour, m.metallicFactor, roughness, m.transmissionFactor, m.ior);
    s.kps = k.kps;
    s.mirrorColor = k.mirrorColor;
    if (hasReflection(s, lobe)) return true;
  }
  return false;
}

bool materialHasTransmission(const Material& m) {
  ShadingMaterial s = toShadingMaterial(m);
  // metallic = metallicFactor x the texel's blue channel: a texel may make a metal factor a
  // dielectric, which transmits (LightsPunctualLamp's shade: factor 1, a transmission texture).
  // The lecture's k_t of such a material is re-mapped per texel too (gltfPbrToLecture): at most
  // the transmission factor.
  if (m.metallicRoughnessTexture >= 0) {
    s.metallic = 0.f;
    s.kt = std::max(s.kt, m.transmissionFactor);
  }
  return hasTransmission(s);
}

}  // namespace diptych::shading
