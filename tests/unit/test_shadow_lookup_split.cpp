// A cube map's lookup runs in two passes (passes/raster/shadow_map_lookup.cpp): the interior
// variant, without the cube-edge path, on the pixels whose taps stay on their own face, then the
// full shader behind a depth test on the pixels it marked. Background pixels are discarded by the
// first and skipped by the second (the depth is cleared to "done"). The split must give the
// one-pass lookup's visibility bit for bit, for every bias and filter it applies to (all but
// receiver_plane, which stays one pass), and background pixels must read lit. Both draw through
// FullscreenResolve, so the lookup, the graph's last pass, must leave its state contract.
#include <gtest/gtest.h>

#include <string>

#include "engine/gl/loader.h"
#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/raster/shadow_map_gl.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

// The GL state that passes/raster/fullscreen_resolve.h promises after every full-screen draw.
struct GlState {
  bool depthTest = true, blend = true, scissor = true, cull = true;
  GLint depthFunc = 0, depthMask = 0, blendSrc = 0, blendDst = 0, clipOrigin = 0, clipDepth = 0;
  GLint drawFramebuffer = -1, vertexArray = -1;
  GLint colorMask[4] = {0, 0, 0, 0};
};

GLint integer(GLenum name) {
  GLint value = -1;
  gl::glGetIntegerv(name, &value);
  return value;
}

GlState glState() {
  GlState s;
  s.depthTest = gl::glIsEnabled(GL_DEPTH_TEST);
  s.blend = gl::glIsEnabled(GL_BLEND);
  s.scissor = gl::glIsEnabled(GL_SCISSOR_TEST);
  s.cull = gl::glIsEnabled(GL_CULL_FACE);
  s.depthFunc = integer(GL_DEPTH_FUNC);
  s.depthMask = integer(GL_DEPTH_WRITEMASK);
  s.blendSrc = integer(GL_BLEND_SRC_RGB);
  s.blendDst = integer(GL_BLEND_DST_RGB);
  s.clipOrigin = integer(GL_CLIP_ORIGIN);
  s.clipDepth = integer(GL_CLIP_DEPTH_MODE);
  s.drawFramebuffer = integer(GL_DRAW_FRAMEBUFFER_BINDING);
  s.vertexArray = integer(GL_VERTEX_ARRAY_BINDING);
  gl::glGetIntegerv(GL_COLOR_WRITEMASK, s.colorMask);
  return s;
}

void expectContract(const GlState& s) {
  EXPECT_FALSE(s.depthTest);
  EXPECT_EQ(s.depthFunc, GL_LESS);
  EXPECT_EQ(s.depthMask, GL_TRUE);
  EXPECT_FALSE(s.blend);
  EXPECT_EQ(s.blendSrc, GL_ONE);
  EXPECT_EQ(s.blendDst, GL_ZERO);
  EXPECT_FALSE(s.scissor);
  EXPECT_FALSE(s.cull);
  for (GLint channel : s.colorMask) EXPECT_EQ(channel, GL_TRUE);
  EXPECT_EQ(s.clipOrigin, GL_LOWER_LEFT);
  EXPECT_EQ(s.clipDepth, GL_ZERO_TO_ONE);
  EXPECT_EQ(s.drawFramebuffer, 0);
  EXPECT_EQ(s.vertexArray, 0);
}

struct Lookup {
  CpuImage visibility, hits;
  GlState after;  // right after the frame, whose last pass is the lookup
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
  const GlState after = glState();
  return {ex.output("sm.visibility"), ex.output("gbuffer.hits"), after};
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
        expectContract(split.after);
        expectContract(one.after);
        EXPECT_GT(background, 1000);  // whitted's sky
        EXPECT_EQ(backgroundLit, background);
        EXPECT_GT(lit, background + 1000);  // lit surfaces beside the sky
        EXPECT_GT(shadowed, 100);
      }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
