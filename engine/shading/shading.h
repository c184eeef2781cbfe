#pragma once
// The shared shading model (shaders/common/shading.glsl) compiled as C++ through GLM, in
// namespace diptych::shading, plus converters from the scene's Light and Material.
// The prelude below is all the C++ side needs; the subset rules are at the top of the .glsl.
#include <cassert>
#include <cmath>

#include <glm/glm.hpp>

#include "engine/scene/scene.h"

namespace diptych::shading {

// GLSL types and built-ins, by name. Using-declarations (not a using-directive) so that only
// GLM's overloads are found, never a C library function of the same name.
using glm::abs;
using glm::clamp;
using glm::cos;
using glm::cross;
using glm::dot;
using glm::exp;
using glm::exp2;
using glm::floor;
using glm::inversesqrt;
using glm::length;
using glm::max;
using glm::min;
using glm::mix;
using glm::pow;
using glm::sqrt;
using glm::vec2;
using glm::vec3;
using glm::vec4;

#define in  // GLSL's default parameter qualifier; parameters are by value in C++ too
// Definitions in a header, always inlined: GLSL passes structs by value (rule 4), and an
// out-of-line call copied each ShadingMaterial (~100 B) and ShadingLight to the stack per call,
// then reloaded it field by field (perf annotate of sampleLight and directTerm, issue 14).
// Inlined, the copies vanish. Every operation and its order are the same, so results are too.
#define SHADING_FN inline __attribute__((always_inline))
// directTerm's precondition: n, v, l unit (or zero). 1e-3 on |v|^2 admits every float rounding
// of a normalised vector and catches a forgotten normalisation (docs/ray-tracing.md). A NaN or
// infinite vector is not checked: bad input reaches the model on purpose in the robustness tests,
// which expect a NaN out and a clean error downstream, not an abort.
#define SHADING_ASSERT_UNIT(v)                             \
  assert(!std::isfinite(dot(v, v)) || dot(v, v) == 0.0f || \
         (dot(v, v) > 0.999f && dot(v, v) < 1.001f))
#include "shaders/common/shading.glsl"
#undef SHADING_ASSERT_UNIT
#undef SHADING_FN
#undef in

static_assert(LIGHT_POINT == int(LightType::Point) &&
              LIGHT_DIRECTIONAL == int(LightType::Directional) &&
              LIGHT_SPOT == int(LightType::Spot) && LIGHT_QUAD_AREA == int(LightType::QuadArea) &&
              LIGHT_DISC_AREA == int(LightType::DiscArea) &&
              LIGHT_SPHERE_AREA == int(LightType::SphereArea));
static_assert(SHADING_MODEL_LECTURE == int(ShadingModel::Lecture) &&
              SHADING_MODEL_GLTF == int(ShadingModel::Gltf));

// Flattens a scene light (cone cosines and emitting area precomputed).
ShadingLight toShadingLight(const Light& light);

// The material's constant parameters; textures and the checker are NOT applied here (see
// engine/rt/surface_point.h, which resolves them at a point). Inline: resolveMaterial runs it per
// shading point, and out of line the ~100-byte result went through the stack before being copied
// into the surface point (perf of the hybrid's shade, issue 14); inlined it is built in place.
inline ShadingMaterial toShadingMaterial(const Material& m) {
  return ShadingMaterial(m.color, m.ka, m.kd, m.ks, m.exponent, m.specularColor, m.kps,
                         m.mirrorColor, m.kt, m.transmitColor, m.emission, m.ior, m.alpha,
                         int(m.model), vec3(m.baseColorFactor), m.metallicFactor, m.roughnessFactor,
                         m.transmissionFactor, m.specularWeight, m.specularTint,
                         m.iridescenceFactor, m.iridescenceIor, m.iridescenceThicknessMaximum);
}

// Whether some point of the material has a reflection / transmission signal (hasReflection /
// hasTransmission of shading.glsl, by the material's own model), for passes that select meshes
// before any hit: textures only scale the glTF factors down, so a metallic-roughness texture is
// taken as possibly smooth (roughness 0) and dielectric (metallic 0), and the factors bound the
// rest; a checker that replaces a re-mapped material's base colour is tried colour by colour.
// `lobe` as hasReflection.
bool materialHasReflection(const Material& material, bool lobe = false);
bool materialHasTransmission(const Material& material);

// KHR_materials_volume: whether rays inside the material are attenuated (Beer-Lambert with
// volumeTransmittance): a volume (thickness > 0; 0 is thin-walled) with an attenuation distance.
inline bool hasVolumeAttenuation(const Material& m) {
  return m.thickness > 0.f && m.attenuationDistance > 0.f;
}

}  // namespace diptych::shading
