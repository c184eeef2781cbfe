// Cached shadow maps (passes/raster/shadow_map_render.cpp, ShadowMapGl::mapsFor): with
// `update: static` the maps are rendered once per world and again only when their key changes
// (light, casters, map settings); the camera is not in the key. Checked by the pass's counters
// (shadow_map_builds, shadow_map_caster_draws: counts, not times) and by comparing visibility
// bit for bit with `update: every_frame` and with a fresh world.
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

struct Frame {
  CpuImage visibility;
  double builds = -1, draws = -1;
};

// gbuffer -> shadow_map (point light: a 6-face cube), 64x48.
CompiledGraph shadowGraph(const Scene& scene, const Camera& camera, const std::string& update,
                          int resolution = 256, float slopeFactor = 2.f) {
  Recipe recipe;
  recipe.passes = {{.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
                   {.name = "sm",
                    .type = "shadow_map",
                    .params = {{"resolution", resolution},
                               {"bias", "slope"},
                               {"factor", slopeFactor},
                               {"filter", "pcf"},
                               {"update", update}},
                    .inputs = {{"hits", "gbuffer.hits"}},
                    .place = "passes[1]"}};
  return compileGraph(recipe, builtinPasses(), scene, FrameSettings{64, 48, camera},
                      {"sm.visibility"});
}

// One frame of shadowGraph on `world`.
Frame shadowFrame(const Scene& scene, RenderWorld& world, const Camera& camera,
                  const std::string& update, int resolution = 256, float slopeFactor = 2.f) {
  const CompiledGraph graph = shadowGraph(scene, camera, update, resolution, slopeFactor);
  GraphExecutor ex(graph, world);
  ex.runFrame();
  Frame f{.visibility = ex.output("sm.visibility")};
  for (std::size_t n = 0; n < graph.nodes.size(); ++n)
    if (graph.nodes[n].name == "sm") {
      f.builds = ex.timings()[n].counters.at("shadow_map_builds");
      f.draws = ex.timings()[n].counters.at("shadow_map_caster_draws");
    }
  return f;
}

Scene whitted() {
  return loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
}

Camera moved(Camera c) {
  c.position += vec3(0.7f, 0.3f, -0.4f);
  return c;
}

TEST(ShadowMapCache, StaticMapsRenderOnceAndGiveTheSameVisibilityAsEveryFrame) {
  const Scene scene = whitted();
  RenderWorld cached(scene, &gl::testing::osmesaContext());
  RenderWorld uncached(scene, &gl::testing::osmesaContext());
  const Frame s1 = shadowFrame(scene, cached, scene.camera, "static");
  const Frame s2 = shadowFrame(scene, cached, scene.camera, "static");
  const Frame s3 = shadowFrame(scene, cached, moved(scene.camera), "static");
  const Frame e1 = shadowFrame(scene, uncached, scene.camera, "every_frame");
  const Frame e2 = shadowFrame(scene, uncached, scene.camera, "every_frame");
  const Frame e3 = shadowFrame(scene, uncached, moved(scene.camera), "every_frame");

  EXPECT_EQ(s1.builds, 1.0);
  EXPECT_GT(s1.draws, 0.0);
  EXPECT_EQ(s2.builds, 0.0) << "same light and casters: the maps are reused";
  EXPECT_EQ(s2.draws, 0.0);
  EXPECT_EQ(s3.builds, 0.0) << "the camera is not in the key";
  for (const Frame* e : {&e1, &e2, &e3}) {
    EXPECT_EQ(e->builds, 1.0);
    EXPECT_EQ(e->draws, s1.draws);
  }
  EXPECT_EQ(s1.visibility.words, e1.visibility.words);
  EXPECT_EQ(s2.visibility.words, e2.visibility.words);
  EXPECT_EQ(s3.visibility.words, e3.visibility.words);
  EXPECT_NE(s1.visibility.words, s3.visibility.words) << "the moved camera must see another image";
  // The static build is a one-time cost of the world; every_frame's is inside its frames.
  EXPECT_GT(cached.oneTimeMs.at("shadow_map build"), 0.0);
  EXPECT_EQ(uncached.oneTimeMs.count("shadow_map build"), 0u);
}

TEST(ShadowMapCache, AChangedLightOrMapSettingRendersAgain) {
  // The world refers to this scene, so moving its light is what an editor moving a light does.
  Scene scene = whitted();
  ASSERT_FALSE(scene.lights.empty());
  RenderWorld world(scene, &gl::testing::osmesaContext());
  const Frame before = shadowFrame(scene, world, scene.camera, "static");
  EXPECT_EQ(before.builds, 1.0);

  scene.lights[0].position += vec3(-3.f, 1.f, 2.f);
  const Frame after = shadowFrame(scene, world, scene.camera, "static");
  EXPECT_EQ(after.builds, 1.0) << "the light moved: its maps must be rendered again";
  RenderWorld fresh(scene, &gl::testing::osmesaContext());
  EXPECT_EQ(after.visibility.words,
            shadowFrame(scene, fresh, scene.camera, "static").visibility.words);
  EXPECT_NE(after.visibility.words, before.visibility.words) << "the shadows must have moved";

  // Another resolution is another set of maps; coming back to 256 finds the 256 maps current.
  EXPECT_EQ(shadowFrame(scene, world, scene.camera, "static", 128).builds, 1.0);
  EXPECT_EQ(shadowFrame(scene, world, scene.camera, "static", 256).builds, 0.0);
  // The slope offset is baked into the depth but keeps no array of its own (a sweep of it would
  // keep one 256^2 x 6 array per value): changing it re-renders the one array, and so does
  // coming back.
  EXPECT_EQ(shadowFrame(scene, world, scene.camera, "static", 256, 3.f).builds, 1.0);
  EXPECT_EQ(shadowFrame(scene, world, scene.camera, "static", 256, 2.f).builds, 1.0);
  EXPECT_EQ(shadowFrame(scene, world, scene.camera, "static", 256, 2.f).builds, 0.0);
}

// With no warm-up the first measured frame renders the static maps: runMeasured drops that
// frame's samples and measures again, so the build is a one-time cost and never in a median.
TEST(ShadowMapCache, AMeasuredFrameThatBuildsTheMapsIsMeasuredAgain) {
  const Scene scene = whitted();
  RenderWorld world(scene, &gl::testing::osmesaContext());
  const CompiledGraph graph = shadowGraph(scene, scene.camera, "static");
  GraphExecutor ex(graph, world);
  int framesRun = 0, lastTotal = 0;
  const GraphExecutor::MeasuredRun run = ex.runMeasured(0, 2, [&](int done, int total) {
    framesRun = done;
    lastTotal = total;
  });
  EXPECT_TRUE(run.repeatedAFrame);
  EXPECT_EQ(framesRun, 3);
  EXPECT_EQ(lastTotal, 3);
  EXPECT_GT(run.oneTimeMs.at("shadow_map build"), 0.0);
  for (const NodeTiming& t : ex.timings()) EXPECT_EQ(t.cpuMs.size(), 2u);

  // The same world again: the maps exist, nothing is built or repeated.
  GraphExecutor again(graph, world);
  const GraphExecutor::MeasuredRun second = again.runMeasured(0, 2);
  EXPECT_FALSE(second.repeatedAFrame);
  EXPECT_TRUE(second.oneTimeMs.empty());
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
