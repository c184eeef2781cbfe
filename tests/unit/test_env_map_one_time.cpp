// env_cube's and env_equirect's maps depend on the environment only (docs/environment-maps.md):
// built once per RenderWorld and reported apart as one-time costs ("env_cube map"), like the
// static shadow map, so that a measured frame which built one is measured again and no frame
// median holds the build. env_sphere's map follows the camera's rotation and stays in frames.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

CompiledGraph envGraph(const Scene& scene, const std::string& type) {
  Recipe recipe;
  recipe.passes = {
      {.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
      {.name = "env", .type = type, .inputs = {{"hits", "gbuffer.hits"}}, .place = "passes[1]"}};
  return compileGraph(recipe, builtinPasses(), scene, FrameSettings{64, 48, scene.camera},
                      {"env.reflection"});
}

Scene whitted() {
  return loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
}

TEST(EnvMapOneTime, CubeMapIsBuiltOnceAndAFrameThatBuildsItIsMeasuredAgain) {
  const Scene scene = whitted();
  RenderWorld world(scene, &gl::testing::osmesaContext());
  const CompiledGraph graph = envGraph(scene, "env_cube");
  GraphExecutor ex(graph, world);
  const GraphExecutor::MeasuredRun run = ex.runMeasured(0, 2);
  EXPECT_TRUE(run.repeatedAFrame) << "the first measured frame built the map";
  ASSERT_EQ(run.oneTimeMs.count("env_cube map"), 1u);
  EXPECT_GE(run.oneTimeMs.at("env_cube map"), 0.0);
  for (const NodeTiming& t : ex.timings()) EXPECT_EQ(t.cpuMs.size(), 2u);

  // The same world again: the map exists, nothing is built or repeated.
  GraphExecutor again(graph, world);
  const GraphExecutor::MeasuredRun second = again.runMeasured(0, 2);
  EXPECT_FALSE(second.repeatedAFrame);
  EXPECT_TRUE(second.oneTimeMs.empty());
  for (std::size_t n = 0; n < graph.nodes.size(); ++n) {
    if (graph.nodes[n].name == "env") {
      EXPECT_EQ(again.timings()[n].counters.at("map_builds"), 0.0);
    }
  }
}

TEST(EnvMapOneTime, SphereMapFollowsTheViewAndIsNotAOneTimeCost) {
  const Scene scene = whitted();
  RenderWorld world(scene, &gl::testing::osmesaContext());
  const CompiledGraph graph = envGraph(scene, "env_sphere");
  // A first executor pays the world's first-use builds (uploads, programs: RenderWorld).
  GraphExecutor(graph, world).runMeasured(1, 1);
  GraphExecutor ex(graph, world);
  const GraphExecutor::MeasuredRun run = ex.runMeasured(0, 2);
  EXPECT_EQ(run.oneTimeMs.count("env_sphere map"), 0u);
  EXPECT_FALSE(run.repeatedAFrame);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
