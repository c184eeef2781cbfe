// GL shade split by the G-buffer's depth (passes/raster/gl_shade.cpp: two Test-mode draws of
// passes/raster/fullscreen_resolve.h): the background program and the surface program, each
// behind an early depth test, give the one-program draw's image bit for bit on a frame with sky
// and surfaces, and leave the depth state as that draw leaves it (a depth mask left off would
// stop the next frame's G-buffer from clearing its depth).
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "engine/gl/loader.h"
#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/recipe.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/raster/gl_shade.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

namespace fs = std::filesystem;

struct DepthState {
  GLint test = 0, func = 0, mask = 0;
  bool operator==(const DepthState&) const = default;
};

struct Shaded {
  CpuImage first, second, hits;  // two frames of one world
  DepthState after;              // after the first frame
};

Shaded shade(const Scene& scene, bool split) {
  const Recipe recipe = loadRecipe(fs::path(DIPTYCH_SAMPLES_DIR) / "graphs/raster.json");
  const CompiledGraph graph =
      compileGraph(recipe, builtinPasses(), scene, FrameSettings{160, 120, scene.camera},
                   {"shade.color", "gbuffer.hits"});
  RenderWorld world(scene, &gl::testing::osmesaContext());
  world.glCached<GlShadeOptions>().split = split;
  GraphExecutor ex(graph, world);
  Shaded out;
  ex.runFrame();
  out.first = ex.output("shade.color");
  out.hits = ex.output("gbuffer.hits");
  out.after.test = gl::glIsEnabled(GL_DEPTH_TEST);
  gl::glGetIntegerv(GL_DEPTH_FUNC, &out.after.func);
  gl::glGetIntegerv(GL_DEPTH_WRITEMASK, &out.after.mask);
  ex.runFrame();
  out.second = ex.output("shade.color");
  return out;
}

TEST(GlShadeSplit, EqualsOneProgramAndKeepsTheDepthState) {
  const Scene whitted = loadScene(fs::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  // A varying environment (six random faces) beside the sample's constant colour, so that a
  // background pixel shaded by the wrong program or left unwritten shows.
  Scene cube = loadScene(fs::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  cube.environment.type = EnvironmentType::Cube;
  for (Image& face : cube.environment.cubeFaces) {
    face = Image(9, 9, 3);
    for (float& v : face.pixels) v = unit(rng);
  }
  for (const Scene* scene : {&whitted, static_cast<const Scene*>(&cube)}) {
    const Shaded split = shade(*scene, true);
    const Shaded one = shade(*scene, false);
    ASSERT_EQ(split.first.words.size(), one.first.words.size());
    long background = 0, surfaces = 0, differ = 0, differNext = 0;
    for (int y = 0; y < split.first.desc.height; ++y)
      for (int x = 0; x < split.first.desc.width; ++x) {
        (split.hits.u(x, y, 0) == 0 ? background : surfaces) += 1;
        for (int ch = 0; ch < 4; ++ch) {
          differ += split.first.f(x, y, ch) != one.first.f(x, y, ch) ? 1 : 0;
          differNext += split.second.f(x, y, ch) != split.first.f(x, y, ch) ? 1 : 0;
        }
      }
    EXPECT_GT(background, 2000);
    EXPECT_GT(surfaces, 2000);
    EXPECT_EQ(differ, 0);
    EXPECT_EQ(differNext, 0);  // the second frame's G-buffer cleared and wrote its depth
    EXPECT_TRUE(split.after == one.after);
    EXPECT_EQ(split.after.mask, GL_TRUE);
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
