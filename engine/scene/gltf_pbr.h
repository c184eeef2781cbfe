#pragma once
// glTF metallic-roughness parameters mapped onto the lecture's coefficients (docs/scene-format.md,
// "glTF material mapping"; docs/materials.md). One function, used by the glTF loader for the
// material's constants and by the CPU surface code per hit where remapsPerTexel (GL:
// scene_shading.glsl sceneApplyGltfPbr), so both give the same coefficients for the same inputs.
#include <algorithm>
#include <optional>
#include <string>

#include "engine/core/math.h"
#include "engine/scene/scene.h"

namespace diptych {

struct LectureCoefficients {
  vec3 color{0.f};  // C
  float kd = 1.f, ks = 0.f, exponent = 1.f;
  vec3 specularColor{1.f};
  float kps = 0.f;
  vec3 mirrorColor{1.f};
  float kt = 0.f;
  vec3 transmitColor{1.f};
};

// The diffuse colour C = base (1 - metallic), metallic clamped to [0, 1]: metals have no diffuse
// term (glTF spec appendix B). gltfPbrToLecture's C, and the one the CPU surface code re-maps a
// textured C to (engine/rt/surface_point.cpp). Inline: it runs per hit there.
inline vec3 gltfDiffuseColor(vec3 base, float metallic) {
  return base * (1.f - std::clamp(metallic, 0.f, 1.f));
}

// Whether the surface code maps the material's glTF inputs to lecture coefficients per texel
// (gltfPbrToLecture at each hit, both sides: engine/rt/surface_point.cpp, scene_shading.glsl)
// rather than using the loader's constants: where a metallic-roughness texture moves metallic and
// roughness (the glTF model reads those too), and, for the lecture's model, where a colour
// texture moves the base colour of a glTF material that is partly metal or transmissive. A
// metal's base colour is its specular colour and a transmissive one's its M_T, which
// C = colour x texel does not carry (C is 0 for a metal): without the re-mapping
// `--shading lecture` showed a textured metal untextured.
inline bool remapsPerTexel(const Material& m) {
  return m.metallicRoughnessTexture >= 0 ||
         (m.model == ShadingModel::Lecture && m.fromGltfPbr && !m.checker && m.colorTexture >= 0 &&
          (m.metallicFactor > 0.f || m.transmissionFactor > 0.f));
}

// base: linear base colour (alpha ignored); metallic, roughness, transmission in [0, 1] (clamped
// here); ior of the dielectric.
LectureCoefficients gltfPbrToLecture(vec3 base, float metallic, float roughness, float transmission,
                                     float ior);

// The reverse, for `--shading gltf` on a lecture material: fills the metallic-roughness inputs
// (baseColorFactor, metallicFactor, roughnessFactor, transmissionFactor) from the lecture's
// coefficients. A coarse rule, documented in docs/materials.md: the mirror share
// k_ps / (k_ps + k_d) becomes metallic, roughness inverts e = 2 / alpha^2 - 2 (0 for mirrors),
// k_t becomes transmission.
void lectureToGltfPbr(Material& m);

// "lecture" or "gltf"; nullopt for anything else.
std::optional<ShadingModel> parseShadingModel(const std::string& name);

// --shading: every material is shaded by `model`. glTF materials keep their lecture mapping for
// the lecture model; lecture materials get lectureToGltfPbr for the glTF model.
void forceShadingModel(Scene& scene, ShadingModel model);

}  // namespace diptych
