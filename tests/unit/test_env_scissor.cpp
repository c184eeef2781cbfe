// The env_* lookups run only inside the window rectangle of the meshes whose material may
// reflect (passes/raster/env_reflection.cpp, screen_rect.h): no reflective pixel may fall outside
// it, and the rectangle must leave the rest of the frame out. Checked against the G-buffer: every
// pixel showing a reflective material gets the environment (a non-zero constant sky here), every
// other pixel 0, and the counted scissor is a small part of the frame.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "engine/shading/shading.h"
#include "gl_test_context.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace {

TEST(EnvScissor, EveryReflectivePixelIsInsideAndTheRestOfTheFrameOutside) {
  // whitted: a mirror sphere and a glass sphere (both reflect) over a checkered floor, sky.
  const Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  const int w = 160, h = 120;
  for (const std::string type : {"env_cube", "env_sphere", "env_equirect"}) {
    Recipe recipe;
    recipe.passes = {
        {.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
        {.name = "env", .type = type, .inputs = {{"hits", "gbuffer.hits"}}, .place = "passes[1]"}};
    const CompiledGraph graph =
        compileGraph(recipe, builtinPasses(), scene, FrameSettings{w, h, scene.camera},
                     {"env.reflection", "gbuffer.hits"});
    RenderWorld world(scene, &gl::testing::osmesaContext());
    GraphExecutor ex(graph, world);
    ex.runFrame();
    const CpuImage& reflection = ex.output("env.reflection");
    const CpuImage& hits = ex.output("gbuffer.hits");
    std::map<int, bool> reflects;  // instance -> its material may reflect
    for (const WorldMesh& mesh : world.geometry().meshes)
      reflects[mesh.instance] = shading::materialHasReflection(scene.material(mesh.material));

    int reflective = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::uint32_t id = hits.u(x, y, 0);
        const bool shows = id != 0 && reflects.at(int(id) - 1);
        reflective += shows ? 1 : 0;
        const float sky = reflection.f(x, y, 2);  // the sky's blue, 0.9
        if (shows)
          ASSERT_GT(sky, 0.5f) << type << ": reflective pixel (" << x << ", " << y << ") left out";
        else
          ASSERT_EQ(sky, 0.f) << type << " (" << x << ", " << y << ")";
      }
    EXPECT_GT(reflective, w * h / 20) << "the spheres are in view";
    for (std::size_t n = 0; n < graph.nodes.size(); ++n)
      if (graph.nodes[n].name == "env") {
        const double scissor = ex.timings()[n].counters.at("env_scissor_pixels");
        EXPECT_GE(scissor, reflective);
        EXPECT_LT(scissor, 0.5 * w * h) << type << ": the floor and sky are left out";
      }
  }
}

}  // namespace
}  // namespace diptych
