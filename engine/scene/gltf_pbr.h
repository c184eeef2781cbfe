#pragma once
// glTF metallic-roughness parameters mapped onto the lecture's coefficients (docs/scene-format.md,
// "glTF material mapping"; docs/materials.md): shaders/common/gltf_lecture.glsl compiled as C++,
// the one definition the loaders' constants, the CPU surface code per texel and the GL scene code
// (gl/scene_shading.glsl, gl_shade.frag) all run, so every side gives the same coefficients for
// the same inputs. Plus the rule for when a material is re-mapped per texel, and --shading.
#include <optional>
#include <string>

#include "engine/core/math.h"
#include "engine/scene/scene.h"

namespace diptych {

// The subset prelude of engine/shading/shading.h, for this file alone: GLM's types and built-ins
// by name, definitions inline (they run per hit in the CPU surface code).
namespace gltf_lecture {
using glm::clamp;
using glm::max;
using glm::mix;
using glm::vec3;
#define in
#define SHADING_FN inline
#include "shaders/common/gltf_lecture.glsl"
#undef SHADING_FN
#undef in
}  // namespace gltf_lecture
using gltf_lecture::gltfDiffuseColor;
using gltf_lecture::gltfPbrToLecture;
using gltf_lecture::LectureCoefficients;

// Whether the surface code maps the material's glTF inputs to lecture coefficients per texel
// (gltfPbrToLecture at each hit, both sides: engine/rt/surface_point.cpp, scene_shading.glsl)
// rather than using the loader's constants: where a metallic-roughness texture moves metallic and
// roughness (the glTF model reads those too), and, for the lecture's model, where a colour
// texture (or a checker, which replaces it as the base colour) moves the base colour of a glTF
// material that is partly metal or transmissive. A metal's base colour is its specular colour
// and a transmissive one's its M_T, which C = colour x texel does not carry (C is 0 for a
// metal): without the re-mapping `--shading lecture` showed a textured metal untextured.
inline bool remapsPerTexel(const Material& m) {
  return m.metallicRoughnessTexture >= 0 ||
         (m.model == ShadingModel::Lecture && m.fromGltfPbr && (m.checker || m.colorTexture >= 0) &&
          (m.metallicFactor > 0.f || m.transmissionFactor > 0.f));
}

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
