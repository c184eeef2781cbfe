// Scene-driven culling of the default hybrid recipe on real sample scenes (the shared-scene half,
// glTF models, is tests/shared_scenes/test_hybrid_culling.cpp).
//
// whitted.json has a shadow-casting point light: nothing may be culled. The same scene with
// castsShadows = false on every light must cull 'shadows' with the documented reason, fill
// shadows.visibility with its fallback 1 for shade, and then produce exactly the image of a recipe
// that has no shadow pass at all (shade alone reads visibility 1 for every light) -- while the
// unculled frame has shadowed pixels, so the comparison can tell the two apart.
#include <gtest/gtest.h>

#include <filesystem>

#include "engine/graph/export.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

const std::filesystem::path kWhitted =
    std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes" / "whitted.json";
constexpr int kW = 160, kH = 120;

// The default hybrid recipe without its light-visibility producer: shade reads no visibility.
Recipe withoutShadowPass() {
  Recipe r = defaultHybridRecipe();
  r.file = "<hybrid recipe without shadows>";
  std::erase_if(r.passes, [](const RecipePass& p) { return p.name == "shadows"; });
  for (RecipePass& p : r.passes) p.inputs.erase("light_visibility");
  return r;
}

TEST(HybridCulling, WhittedKeepsEveryPassAndCastsShadows) {
  auto f = testing::renderHybridFrame(kWhitted, kW, kH, {"shade.color", "shadows.visibility"});
  // Whitted's checker is procedural: no colour texture for the texture_filtering slot.
  for (const GraphPass& p : f->graph.passes)
    EXPECT_EQ(p.culled, p.name == "texture_filtering") << p.name << " culled: " << p.cullReason;
  EXPECT_EQ(testing::scheduledNode(f->graph, "default:shadows.visibility"), nullptr);
  ASSERT_NE(testing::scheduledNode(f->graph, "shadows"), nullptr);
  const CpuImage& vis = f->output("shadows.visibility");
  int zeros = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) zeros += vis.f(x, y, 0) == 0.f;
  EXPECT_GT(zeros, 0) << "the spheres must shadow the floor";
}

// Whitted has no colour texture: the texture_filtering slot is culled, and because shade reads
// its albedo as an optional input, the slot leaves the frame entirely: no pass node, no default
// fill, shade does not read it, and the export says so (DESIGN.md: leave out of a frame whatever
// the scene does not need). The image is that of a recipe without the slot at all.
TEST(HybridCulling, WhittedFrameHasNoTextureFilteringNodeOrFill) {
  auto f = testing::renderHybridFrame(kWhitted, kW, kH, {});
  EXPECT_TRUE(f->pass("texture_filtering")->culled);
  EXPECT_EQ(testing::scheduledNode(f->graph, "texture_filtering"), nullptr);
  EXPECT_EQ(testing::scheduledNode(f->graph, "default:texture_filtering.albedo"), nullptr);
  for (const GraphNode& n : f->graph.nodes)
    EXPECT_EQ(n.name.find("texture_filtering"), std::string::npos) << n.name;
  const GraphPass* shade = f->pass("shade");
  for (ResourceId r : shade->reads)
    EXPECT_NE(f->graph.resources[r].name, "texture_filtering.albedo");
  ASSERT_EQ(shade->inputsLeftOut.size(), 1u);
  EXPECT_EQ(shade->inputsLeftOut[0],
            "albedo <- texture_filtering.albedo (scene has no colour-textured materials)");
  const nlohmann::json j = graphToJson(f->graph, nullptr);
  for (const auto& node : j["schedule"])
    EXPECT_EQ(node["name"].get<std::string>().find("texture_filtering"), std::string::npos);

  Recipe bare = defaultHybridRecipe();
  bare.file = "<hybrid recipe without texture_filtering>";
  std::erase_if(bare.passes, [](const RecipePass& p) { return p.name == "texture_filtering"; });
  for (RecipePass& p : bare.passes) p.inputs.erase("albedo");
  auto without = testing::renderHybridFrame(loadScene(kWhitted), kW, kH, {}, bare);
  EXPECT_EQ(f->output("shade.color").words, without->output("shade.color").words);
}

TEST(HybridCulling, LightsThatCastNoShadowsCullTheShadowPassAndShadeReadsVisibilityOne) {
  Scene scene = loadScene(kWhitted);
  ASSERT_FALSE(scene.lights.empty());
  for (Light& l : scene.lights) l.castsShadows = false;
  auto culled = testing::renderHybridFrame(scene, kW, kH, {"shade.color", "shadows.visibility"});
  const GraphPass* shadows = culled->pass("shadows");
  ASSERT_NE(shadows, nullptr);
  EXPECT_TRUE(shadows->culled);
  EXPECT_EQ(shadows->cullReason, "scene has no shadow-casting lights");
  EXPECT_FALSE(culled->pass("shade")->culled);
  EXPECT_FALSE(culled->pass("gbuffer")->culled);
  EXPECT_EQ(testing::scheduledNode(culled->graph, "shadows"), nullptr);
  ASSERT_NE(testing::scheduledNode(culled->graph, "default:shadows.visibility"), nullptr);

  // What shade read: the fallback, 1 everywhere, in every light's layer.
  const CpuImage& vis = culled->output("shadows.visibility");
  ASSERT_EQ(vis.desc.layers, int(scene.lights.size()));
  for (int l = 0; l < vis.desc.layers; ++l)
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) ASSERT_EQ(vis.f(x, y, 0, l), 1.f) << x << "," << y << "," << l;

  auto shadeOnly = testing::renderHybridFrame(scene, kW, kH, {}, withoutShadowPass());
  auto full = testing::renderHybridFrame(kWhitted, kW, kH, {});
  const CpuImage& a = culled->output("shade.color");
  const CpuImage& b = shadeOnly->output("shade.color");
  const CpuImage& c = full->output("shade.color");
  EXPECT_EQ(a.words, b.words) << "culled frame differs from a frame without a shadow pass";
  EXPECT_NE(a.words, c.words) << "shadows must change the image, or this test proves nothing";
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
