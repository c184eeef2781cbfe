// The shadow-map lookup uploads its light frusta only when they change
// (passes/raster/shadow_map_lookup.cpp, uploadFrusta): a changed light must still reach the
// lookup. PCSS's light size is in the uploaded light data but not in the cached maps' key, so a
// second frame with another size keeps the maps (no build) and must read the new size: its
// visibility equals a fresh world's and differs from the first frame's.
#include <gtest/gtest.h>

#include <filesystem>

#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"
#include "tests/unit/gl_test_context.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

struct Frame {
  CpuImage visibility;
  double builds = -1;
};

// gbuffer -> shadow_map (static maps, PCSS with light diameter `fraction` of the scene's), 64x48.
Frame pcssFrame(const Scene& scene, RenderWorld& world, double fraction) {
  Recipe recipe;
  recipe.passes = {{.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
                   {.name = "sm",
                    .type = "shadow_map",
                    .params = {{"resolution", 256},
                               {"bias", "slope"},
                               {"filter", "pcss"},
                               {"light_fraction", fraction},
                               {"update", "static"}},
                    .inputs = {{"hits", "gbuffer.hits"}},
                    .place = "passes[1]"}};
  const CompiledGraph graph = compileGraph(recipe, builtinPasses(), scene,
                                           FrameSettings{64, 48, scene.camera}, {"sm.visibility"});
  GraphExecutor ex(graph, world);
  ex.runFrame();
  Frame f{.visibility = ex.output("sm.visibility")};
  for (std::size_t n = 0; n < graph.nodes.size(); ++n)
    if (graph.nodes[n].name == "sm") f.builds = ex.timings()[n].counters.at("shadow_map_builds");
  return f;
}

TEST(ShadowMapUpload, AChangedLightSizeReachesTheLookupWithTheMapsCached) {
  const Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  RenderWorld world(scene, &gl::testing::osmesaContext());
  const Frame small = pcssFrame(scene, world, 0.005);
  const Frame large = pcssFrame(scene, world, 0.05);
  EXPECT_EQ(small.builds, 1.0);
  EXPECT_EQ(large.builds, 0.0) << "the light size is not in the maps' key";
  RenderWorld fresh(scene, &gl::testing::osmesaContext());
  EXPECT_EQ(large.visibility.words, pcssFrame(scene, fresh, 0.05).visibility.words);
  EXPECT_NE(large.visibility.words, small.visibility.words) << "a larger light, wider penumbrae";
  // And back: the first size's visibility again.
  EXPECT_EQ(pcssFrame(scene, world, 0.005).visibility.words, small.visibility.words);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
