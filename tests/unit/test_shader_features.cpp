// Scene shader permutations (engine/gl/shader_features.h): which paths a scene's GL programs
// keep. Folding a path the scene uses would shade it wrongly, so the rule is checked on real
// samples and on a scene built to have every feature; that the folded programs shade as the
// CPU does is GlShade.MatchesCpuShadeOnEverySampleWithTheSameProducers.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "engine/gl/shader_features.h"
#include "engine/scene/load.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

std::map<std::string, std::string> definesOf(const Scene& scene) {
  std::map<std::string, std::string> out;
  for (const gl::ShaderDefine& d : gl::sceneShaderDefines(scene)) out[d.name] = d.value;
  return out;
}

Scene sample(const char* name) {
  return loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes" / name);
}

TEST(ShaderFeatures, WhittedKeepsTheCheckerAndOnePointLightAndFoldsTextures) {
  const auto d = definesOf(sample("whitted.json"));
  EXPECT_EQ(d.count("DIPTYCH_SCENE_FEATURES"), 1u);
  EXPECT_EQ(d.at("DIPTYCH_SCENE_TEXTURES"), "0");
  EXPECT_EQ(d.at("DIPTYCH_SCENE_NORMAL_MAPS"), "0");
  EXPECT_EQ(d.at("DIPTYCH_SCENE_CHECKER"), "1");
  EXPECT_EQ(d.at("DIPTYCH_SCENE_REMAP"), "0");  // a lecture checker: no glTF inputs to re-map
  EXPECT_EQ(d.at("DIPTYCH_SCENE_IRIDESCENCE"), "0");
  EXPECT_EQ(d.at("DIPTYCH_SCENE_MODEL"), std::to_string(int(ShadingModel::Lecture)));
  EXPECT_EQ(d.at("DIPTYCH_SCENE_LIGHT_TYPE"), std::to_string(int(LightType::Point)));
}

TEST(ShaderFeatures, TexturedSampleKeepsTheTexturePaths) {
  const auto d = definesOf(sample("textures.json"));
  EXPECT_EQ(d.at("DIPTYCH_SCENE_TEXTURES"), "1");
}

TEST(ShaderFeatures, EveryFeatureAndMixtureIsKept) {
  Scene scene = sample("whitted.json");
  ASSERT_GE(scene.materials.size(), 2u);
  scene.materials[0].normalTexture = 0;
  scene.materials[1].emissionTexture = 0;
  scene.materials[1].model = ShadingModel::Gltf;
  Light spot = scene.lights.at(0);
  spot.type = LightType::Spot;
  scene.lights.push_back(spot);
  const auto d = definesOf(scene);
  EXPECT_EQ(d.at("DIPTYCH_SCENE_TEXTURES"), "1");
  EXPECT_EQ(d.at("DIPTYCH_SCENE_NORMAL_MAPS"), "1");
  EXPECT_EQ(d.at("DIPTYCH_SCENE_MODEL"), "-1");       // lecture and glTF both present
  EXPECT_EQ(d.at("DIPTYCH_SCENE_LIGHT_TYPE"), "-1");  // point and spot
}

TEST(ShaderFeatures, AFilmIsKeptOnlyForAGltfMaterialWithAStrength) {
  Scene scene = sample("whitted.json");
  ASSERT_GE(scene.materials.size(), 1u);
  scene.materials[0].iridescenceFactor = 0.5f;  // a lecture material: pbr.glsl never runs
  EXPECT_EQ(definesOf(scene).at("DIPTYCH_SCENE_IRIDESCENCE"), "0");
  scene.materials[0].model = ShadingModel::Gltf;
  EXPECT_EQ(definesOf(scene).at("DIPTYCH_SCENE_IRIDESCENCE"), "1");
  scene.materials[0].iridescenceFactor = 0.f;
  EXPECT_EQ(definesOf(scene).at("DIPTYCH_SCENE_IRIDESCENCE"), "0");
}

// Gate 8 (remapsPerTexel) is kept where a material takes its lecture coefficients per texel: a
// metallic-roughness texture, or under the lecture's model a glTF metal with a colour texture or
// a checker, which has no texture at all.
TEST(ShaderFeatures, TheRemapIsKeptOnlyForAMaterialRemappedPerTexel) {
  Scene scene = sample("whitted.json");
  Material& m = scene.materials.at(0);
  m.checker = Checker{};
  m.fromGltfPbr = true;
  m.metallicFactor = 0.f;  // a dielectric: C = colour x texel carries the checker
  EXPECT_EQ(definesOf(scene).at("DIPTYCH_SCENE_REMAP"), "0");
  m.metallicFactor = 1.f;
  EXPECT_EQ(definesOf(scene).at("DIPTYCH_SCENE_REMAP"), "1");
  EXPECT_EQ(definesOf(scene).at("DIPTYCH_SCENE_TEXTURES"), "0");
  m.checker.reset();
  m.metallicRoughnessTexture = 0;
  EXPECT_EQ(definesOf(scene).at("DIPTYCH_SCENE_REMAP"), "1");
}

TEST(ShaderFeatures, TheDefaultMaterialCountsOnlyWhereAMeshUsesIt) {
  Scene scene = sample("whitted.json");
  for (Material& m : scene.materials) m.model = ShadingModel::Gltf;
  EXPECT_EQ(definesOf(scene).at("DIPTYCH_SCENE_MODEL"), std::to_string(int(ShadingModel::Gltf)));
  scene.meshes.at(0).material = -1;  // now shaded with the default (lecture) material
  EXPECT_EQ(definesOf(scene).at("DIPTYCH_SCENE_MODEL"), "-1");
  scene.lights.clear();
  EXPECT_EQ(definesOf(scene).at("DIPTYCH_SCENE_LIGHT_TYPE"), "-1");
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
