#include "engine/gl/shader_features.h"

#include <string>

#include "engine/scene/gltf_pbr.h"

namespace diptych::gl {

std::vector<ShaderDefine> sceneShaderDefines(const Scene& scene) {
  bool textures = false, normalMaps = false, bump = false, checker = false, film = false;
  bool remap = false;
  int model = -2;  // none seen yet
  auto visit = [&](const Material& m) {
    // As packMaterial: a checker replaces the colour texture.
    textures |= (!m.checker && m.colorTexture >= 0) || m.emissionTexture >= 0 ||
                m.metallicRoughnessTexture >= 0 || m.occlusionTexture >= 0;
    normalMaps |= m.normalTexture >= 0;
    bump |= m.bump.has_value();
    checker |= m.checker.has_value();
    remap |= remapsPerTexel(m);  // gate 8 of scene_shading.glsl sceneMaterialLod
    // A film shades only under the glTF model (pbr.glsl), and only with a strength above 0;
    // its textures are then sampled (scene_shading.glsl sceneMaterialLod).
    const bool filmed = m.model == ShadingModel::Gltf && m.iridescenceFactor > 0.f;
    film |= filmed;
    textures |= filmed && (m.iridescenceTexture >= 0 || m.iridescenceThicknessTexture >= 0);
    if (model == -2) model = int(m.model);
    if (int(m.model) != model) model = -1;
  };
  // The default material (GL entry 0) is shaded only where a mesh has none.
  for (const Mesh& mesh : scene.meshes)
    if (mesh.material < 0 || mesh.material >= int(scene.materials.size())) {
      visit(scene.material(-1));
      break;
    }
  for (const Material& m : scene.materials) visit(m);
  if (model == -2) model = -1;
  int lightType = scene.lights.empty() ? -1 : int(scene.lights.front().type);
  for (const Light& l : scene.lights)
    if (int(l.type) != lightType) lightType = -1;
  auto flag = [](bool b) { return std::string(b ? "1" : "0"); };
  return {{"DIPTYCH_SCENE_FEATURES", ""},
          {"DIPTYCH_SCENE_TEXTURES", flag(textures)},
          {"DIPTYCH_SCENE_NORMAL_MAPS", flag(normalMaps)},
          {"DIPTYCH_SCENE_BUMP", flag(bump)},
          {"DIPTYCH_SCENE_CHECKER", flag(checker)},
          {"DIPTYCH_SCENE_REMAP", flag(remap)},
          {"DIPTYCH_SCENE_IRIDESCENCE", flag(film)},
          {"DIPTYCH_SCENE_MODEL", std::to_string(model)},
          {"DIPTYCH_SCENE_LIGHT_TYPE", std::to_string(lightType)}};
}

std::vector<ShaderDefine> withDefines(std::vector<ShaderDefine> base,
                                      const std::vector<ShaderDefine>& extra) {
  base.insert(base.end(), extra.begin(), extra.end());
  return base;
}

}  // namespace diptych::gl
