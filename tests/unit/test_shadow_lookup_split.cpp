// A cube map's lookup runs in two passes (passes/raster/shadow_map_lookup.cpp): the interior
// variant, without the cube-edge path, on the pixels whose taps stay on their own face, then the
// full shader behind a depth test on the pixels it marked. Background pixels are discarded by the
// first and skipped by the second (the depth is cleared to "done"). The split must give the
// one-pass lookup's visibility bit for bit, for every bias and filter it applies to (all but
// receiver_plane, which stays one pass), and background pixels must read lit.
#include <gtest/gtest.h>

#include <string>

#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/raster/shadow_map_gl.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace {

struct Lookup {
  CpuImage visibility, hits;
};

Lookup lookup(const Scene& scene, bool split, const std::string& bias, const std::string& filter,
              int resolution) {
  Recipe recipe;
  recipe.passes = {
      {.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
      {.name = "sm",
       .type = "shadow_map",
       .params = {{"resolution", resolution}, {"bias", bias}, {"filter", filter}, {"kernel", 3}},
       .inputs = {{"hits", "gbuffer.hits"}},
       .place = "passes[1]"}};
  const CompiledGraph graph =
      compileGraph(recipe, builtinPasses(), scene, FrameSettings{160, 120, scene.camera},
                   {"sm.visibility", "gbuffer.hits"});
  RenderWorld world(scene, &gl::testing::osmesaContext());
  world.glCached<shadowmap::ShadowMapGl>().splitCube = split;
  GraphExecutor ex(graph, world);
  ex.runFrame();
  return {ex.output("sm.visibility"), ex.output("gbuffer.hits")};
}

TEST(ShadowLookup, SplitCubeEqualsOnePass) {
  const Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  ASSERT_EQ(scene.lights.size(), 1u);
  ASSERT_EQ(scene.lights[0].type, LightType::Point);  // a cube map: the split applies
  // A coarse map puts many pixels' taps across a face edge (the full pass's share); a fine one
  // leaves most to the interior pass.
  for (const char* bias : {"none", "constant", "slope", "normal_offset", "adaptive"})
    for (const char* filter : {"none", "pcf", "poisson", "pcss"})
      for (int resolution : {64, 1024}) {
        SCOPED_TRACE(std::string(bias) + " " + filter + " " + std::to_string(resolution));
        const Lookup split = lookup(scene, true, bias, filter, resolution);
        const Lookup one = lookup(scene, false, bias, filter, resolution);
        ASSERT_EQ(split.visibility.words.size(), one.visibility.words.size());
        int differ = 0, background = 0, backgroundLit = 0, lit = 0, shadowed = 0;
        for (int y = 0; y < split.visibility.desc.height; ++y)
          for (int x = 0; x < split.visibility.desc.width; ++x) {
            const float v = split.visibility.f(x, y, 0);
            differ += v != one.visibility.f(x, y, 0) ? 1 : 0;
            lit += v == 1.f ? 1 : 0;
            shadowed += v == 0.f ? 1 : 0;
            if (split.hits.words[split.hits.index(x, y, 0, 0)] == 0) {
              ++background;
              backgroundLit += v == 1.f ? 1 : 0;
            }
          }
        EXPECT_EQ(differ, 0);
        EXPECT_GT(background, 1000);  // whitted's sky
        EXPECT_EQ(backgroundLit, background);
        EXPECT_GT(lit, background + 1000);  // lit surfaces beside the sky
        EXPECT_GT(shadowed, 100);
      }
}

}  // namespace
}  // namespace diptych
