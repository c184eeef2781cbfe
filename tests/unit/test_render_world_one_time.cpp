// What a RenderWorld builds on first use (Embree device and BVH, GL scene and shading uploads,
// the textures with their mip chains, GL programs and targets) is a one-time cost (issue 9):
// recorded in oneTimeMs, so that a measured frame which paid for it (with no warm-up, the first) is
// measured again and no frame median holds it, and a second run on the same world pays nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "engine/gl/shading_buffers.h"
#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/recipe.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

Scene sample(const std::string& name) {
  return loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes" / name);
}

CompiledGraph compile(const Recipe& recipe, const Scene& scene) {
  return compileGraph(recipe, builtinPasses(), scene, FrameSettings{64, 48, scene.camera});
}

Recipe graphFile(const std::string& name) {
  return loadRecipe(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "graphs" / name);
}

TEST(RenderWorldOneTime, FirstUseBuildsAreOneTimeAndTheirFrameIsMeasuredAgain) {
  const Scene scene = sample("whitted.json");
  RenderWorld world(scene, &gl::testing::osmesaContext());
  const CompiledGraph graph = compile(defaultHybridRecipe(), scene);
  GraphExecutor ex(graph, world);
  int framesRun = 0;
  const GraphExecutor::MeasuredRun run =
      ex.runMeasured(0, 2, [&](int done, int) { framesRun = done; });
  EXPECT_TRUE(run.repeatedAFrame) << "the first measured frame built the BVH and uploaded";
  EXPECT_EQ(framesRun, 3);
  for (const char* what : {RenderWorld::kBvhBuild, RenderWorld::kGlSceneUpload,
                           RenderWorld::kGlShadingUpload, RenderWorld::kGlSetup}) {
    ASSERT_EQ(run.oneTimeMs.count(what), 1u) << what;
    EXPECT_GT(run.oneTimeMs.at(what), 0.0) << what;
  }
  for (const NodeTiming& t : ex.timings()) EXPECT_EQ(t.cpuMs.size(), 2u);

  // The same world again: everything exists, nothing is built or repeated.
  GraphExecutor again(graph, world);
  const GraphExecutor::MeasuredRun second = again.runMeasured(0, 2);
  EXPECT_FALSE(second.repeatedAFrame);
  EXPECT_TRUE(second.oneTimeMs.empty());
}

TEST(RenderWorldOneTime, ACpuOnlyFrameBuildsTheBvhAndTouchesNoGl) {
  const Scene scene = sample("whitted.json");
  RenderWorld world(scene);  // no context: a GL upload would throw
  const CompiledGraph graph = compile(graphFile("whitted.json"), scene);
  ASSERT_FALSE(graph.usesGl());
  GraphExecutor ex(graph, world);
  const GraphExecutor::MeasuredRun run = ex.runMeasured(0, 1);
  EXPECT_TRUE(run.repeatedAFrame);
  ASSERT_EQ(run.oneTimeMs.size(), 1u);
  EXPECT_GT(run.oneTimeMs.at(RenderWorld::kBvhBuild), 0.0);
}

// With a warm-up frame the builds fall there: reported all the same, and no frame is repeated.
TEST(RenderWorldOneTime, BuildsInAWarmUpFrameAreReportedAndNotRepeated) {
  const Scene scene = sample("textures.json");
  RenderWorld world(scene, &gl::testing::osmesaContext());
  const CompiledGraph graph = compile(graphFile("raster.json"), scene);
  GraphExecutor ex(graph, world);
  const GraphExecutor::MeasuredRun run = ex.runMeasured(1, 1);
  EXPECT_FALSE(run.repeatedAFrame);
  EXPECT_GT(run.oneTimeMs.at(RenderWorld::kGlShadingUpload), 0.0);
  EXPECT_GT(run.oneTimeMs.at(RenderWorld::kGlTextureUpload), 0.0) << "textures and mip chains";
  EXPECT_GT(run.oneTimeMs.at(RenderWorld::kGlSetup), 0.0);
  for (const NodeTiming& t : ex.timings()) EXPECT_EQ(t.cpuMs.size(), 1u);
}

// The hybrid frame's GL work is its visibility G-buffer, which reads no texture: a textured
// scene's textures are not uploaded for it ("leave out of a frame whatever it does not need"),
// and the GL-shaded frame that follows on the same world uploads them then.
TEST(RenderWorldOneTime, TheHybridFrameUploadsNoTexture) {
  const Scene scene = sample("textures.json");
  ASSERT_FALSE(scene.textures.empty());
  RenderWorld world(scene, &gl::testing::osmesaContext());
  const GraphExecutor::MeasuredRun hybrid =
      GraphExecutor(compile(defaultHybridRecipe(), scene), world).runMeasured(1, 1);
  EXPECT_EQ(hybrid.oneTimeMs.count(RenderWorld::kGlTextureUpload), 0u);
  EXPECT_EQ(hybrid.oneTimeMs.count(RenderWorld::kGlShadingUpload), 1u) << "materials, masks";
  EXPECT_FALSE(world.glShading(false).textures.texels) << "nothing uploaded behind the counter";

  const GraphExecutor::MeasuredRun raster =
      GraphExecutor(compile(graphFile("raster.json"), scene), world).runMeasured(1, 1);
  EXPECT_GT(raster.oneTimeMs.at(RenderWorld::kGlTextureUpload), 0.0);
  EXPECT_EQ(raster.oneTimeMs.count(RenderWorld::kGlShadingUpload), 0u) << "uploaded once";
  EXPECT_EQ(world.glShading().textures.count, int(scene.textures.size()));
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
