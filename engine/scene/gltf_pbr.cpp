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
  m.color = base * (1.f - metallic);
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

}  // namespace diptych
