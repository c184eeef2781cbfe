// Whether the reflection / transmission signals exist follows the material's own model
// (shading.glsl hasReflection / hasTransmission), not the lecture mapping's k_ps / k_t. On a glTF
// file (samples/scenes/blender-point-light.gltf, its materials edited here):
//   Glossy  roughness 0.2 with KHR_materials_specular specularFactor 0: the lecture mapping keeps
//           k_ps = F0 (1 - r) > 0, but the glTF model has no specular lobe: no reflection signal;
//   Ground  roughness 0.5 with KHR_materials_ior ior 1: F0 = 0, so k_ps = 0, but Schlick's
//           Fresnel still reflects at grazing: the reflection signal is traced;
//   Glass   transmission 1: the transmission signal, as before.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/recipe.h"
#include "engine/graph/render_world.h"
#include "engine/scene/gltf_pbr.h"
#include "engine/scene/load.h"
#include "engine/shading/shading.h"
#include "gl_test_context.h"
#include "passes/common/hits_texel.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

namespace fs = std::filesystem;

Scene editedScene() {
  const fs::path dir = testing::scratchDir("material_gates");
  nlohmann::json gltf;
  std::ifstream(fs::path(DIPTYCH_SAMPLES_DIR) / "scenes" / "blender-point-light.gltf") >> gltf;
  for (nlohmann::json& m : gltf["materials"]) {
    if (m["name"] == "Glossy") m["extensions"]["KHR_materials_specular"] = {{"specularFactor", 0}};
    if (m["name"] == "Ground") {
      m["pbrMetallicRoughness"]["roughnessFactor"] = 0.5;
      m["extensions"]["KHR_materials_ior"] = {{"ior", 1.0}};
    }
  }
  gltf["extensionsUsed"].push_back("KHR_materials_specular");
  gltf["extensionsUsed"].push_back("KHR_materials_ior");
  // The buffers are embedded (data URIs), so the edited copy stands alone.
  std::ofstream(dir / "edited.gltf") << gltf.dump();
  // A white sky, so that every traced reflection ray brings back something.
  const nlohmann::json scene = {{"environment", {{"color", {1, 1, 1}}}},
                                {"objects", {{{"type", "gltf"}, {"file", "edited.gltf"}}}}};
  std::ofstream(dir / "scene.json") << scene.dump();
  return loadScene(dir / "scene.json");
}

const Material& named(const Scene& s, const std::string& name) {
  for (const Material& m : s.materials)
    if (m.name == name) return m;
  ADD_FAILURE() << "no material " << name;
  return s.materials.front();
}

TEST(MaterialGates, TheGltfModelDecidesNotTheLectureMapping) {
  const Scene scene = editedScene();
  const Material& glossy = named(scene, "Glossy");
  const Material& ground = named(scene, "Ground");
  const Material& glass = named(scene, "Glass");
  EXPECT_GT(glossy.kps, 0.f);  // the lecture mapping alone would trace it
  EXPECT_FALSE(shading::materialHasReflection(glossy));
  EXPECT_EQ(ground.kps, 0.f);  // ... and would not trace this one
  EXPECT_TRUE(shading::materialHasReflection(ground));
  EXPECT_TRUE(shading::materialHasTransmission(glass));
  EXPECT_FALSE(shading::materialHasTransmission(ground));
}

// Pixels per material name, and how many of them have a non-zero reflection / transmission,
// after one frame of gbuffer + the two producers.
struct Counts {
  std::map<std::string, int> pixels, reflected, transmitted;
};
Counts countSignals(const Scene& scene, const std::string& reflection,
                    const std::string& transmission);

// The exact producers follow the same gate: rt_reflection leaves the Glossy sphere at 0 and
// traces the Ground, rt_transmission traces the Glass.
TEST(MaterialGates, RtProducersTraceWhatTheModelWeights) {
  Counts c = countSignals(editedScene(), "rt_reflection", "rt_transmission");
  ASSERT_GT(c.pixels["Glossy"], 50);
  ASSERT_GT(c.pixels["Ground"], 500);
  ASSERT_GT(c.pixels["Glass"], 50);
  EXPECT_EQ(c.reflected["Glossy"], 0);
  EXPECT_GT(c.reflected["Ground"], c.pixels["Ground"] / 2);
  EXPECT_GT(c.transmitted["Glass"], c.pixels["Glass"] / 2);
  EXPECT_EQ(c.transmitted["Ground"], 0);
}

// The GL producers decide by the material before rebuilding the surface (the gate bits packed
// by engine/gl/shading_buffers.cpp, scene_shading.glsl sceneHitMay*): the same pixels as the
// exact producers, in particular the Ground (k_ps = 0, yet the glTF model reflects) keeps its
// environment reflection, with GGX-prefiltered levels (the lobe gate) and without.
TEST(MaterialGates, GlProducersGateByTheModelBeforeRebuildingTheSurface) {
  const Scene scene = editedScene();
  for (const char* reflection : {"env_cube", "env_cube:prefilter=false"}) {
    SCOPED_TRACE(reflection);
    Counts c = countSignals(scene, reflection, "sorted_blend");
    ASSERT_GT(c.pixels["Ground"], 500);
    EXPECT_EQ(c.reflected["Glossy"], 0);
    EXPECT_GT(c.reflected["Ground"], c.pixels["Ground"] / 2);
    EXPECT_GT(c.transmitted["Glass"], c.pixels["Glass"] / 2);
    EXPECT_EQ(c.transmitted["Ground"], 0);
  }
}

Counts countSignals(const Scene& scene, const std::string& reflection,
                    const std::string& transmission) {
  nlohmann::json reflectionPass = {{"name", "refl"}, {"inputs", {{"hits", "gbuffer.hits"}}}};
  const auto colon = reflection.find(':');
  reflectionPass["type"] = reflection.substr(0, colon);
  if (colon != std::string::npos) reflectionPass["params"] = {{"prefilter", false}};
  const nlohmann::json recipe = {
      {"passes",
       {{{"name", "gbuffer"}, {"type", "gbuffer"}},
        reflectionPass,
        {{"name", "trans"}, {"type", transmission}, {"inputs", {{"hits", "gbuffer.hits"}}}}}},
      {"outputs", {"refl.reflection", "trans.transmission", "gbuffer.hits"}}};
  const FrameSettings frame{.width = 96, .height = 64, .camera = scene.camera};
  const CompiledGraph graph =
      compileGraph(parseRecipe(recipe, "test"), builtinPasses(), scene, frame);
  RenderWorld world(scene, &gl::testing::osmesaContext());  // the G-buffer is GL
  GraphExecutor executor(graph, world);
  executor.runFrame();
  const CpuImage& hits = executor.output("gbuffer.hits");
  const CpuImage& refl = executor.output("refl.reflection");
  const CpuImage& trans = executor.output("trans.transmission");
  Counts c;
  auto& [pixels, reflected, transmitted] = c;
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x) {
      const auto texel = hitsTexel(hits, x, y);
      if (!texel) continue;
      const std::string& name =
          scene
              .material(
                  scene.meshes[scene.instances.at(std::size_t(texel->instance)).mesh].material)
              .name;
      ++pixels[name];
      if (refl.f(x, y, 0) + refl.f(x, y, 1) + refl.f(x, y, 2) > 0.f) ++reflected[name];
      if (trans.f(x, y, 0) + trans.f(x, y, 1) + trans.f(x, y, 2) > 0.f) ++transmitted[name];
    }
  return c;
}

// A checker replaces a re-mapped glTF material's base colour (remapsPerTexel under the lecture's
// model), so the loader's constants, mapped from baseColorFactor, do not bound its texels: a
// black metal (k_ps 0) with a bright checker reflects wherever the checker is bright, and the
// pass gate must say so.
TEST(MaterialGates, ACheckerOnABlackGltfMetalStillReflects) {
  Material m;
  m.model = ShadingModel::Lecture;
  m.fromGltfPbr = true;
  m.metallicFactor = 1.f;
  m.roughnessFactor = 0.f;
  m.baseColorFactor = vec4(0.f, 0.f, 0.f, 1.f);
  const LectureCoefficients k = gltfPbrToLecture(vec3(0.f), 1.f, 0.f, 0.f, m.ior);
  m.kps = k.kps;  // the loader's constant: 0 for a black metal
  ASSERT_EQ(m.kps, 0.f);
  EXPECT_FALSE(shading::materialHasReflection(m));
  m.checker = Checker{vec3(0.9f), vec3(0.f), 4.f};
  EXPECT_TRUE(shading::materialHasReflection(m));
  m.checker->colorA = vec3(0.f);  // both colours black: nothing reflects
  EXPECT_FALSE(shading::materialHasReflection(m));
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
