#include "engine/shading/shading.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

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
  return hasReflection(s, lobe);
}

bool materialHasTransmission(const Material& m) {
  return hasTransmission(toShadingMaterial(m));
}

}  // namespace diptych::shading
