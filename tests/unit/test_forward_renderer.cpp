// The forward renderer's environment background (engine/gl/forward_renderer.cpp): when the
// meshes write depth it is drawn after them, behind a depth test that passes only where no mesh
// wrote (what engines do with the sky, so covered pixels skip its cube lookup); otherwise first,
// under them. Both orders must give the same image, texel for texel. Either way the renderer
// leaves the GL state FullscreenResolve leaves (engine/gl/forward_renderer.h), not its own.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/gl/forward_renderer.h"
#include "engine/gl/loader.h"
#include "engine/gl/transfer.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

// A lit quad over the left part of the view, in front of a constant sky (0.2, 0.4, 0.8).
Scene quadOverSky() {
  const auto dir = ::diptych::testing::scratchDir("diptych_forward_renderer");
  std::filesystem::create_directories(dir);
  const auto path = dir / "quad.json";
  std::ofstream(path) << R"({"camera": {"position": [0,0,5], "target": [0,0,0], "fov": 45},
    "environment": {"color": [0.2, 0.4, 0.8]},
    "materials": {"m": {"kd": 0.8, "color": [0.9, 0.5, 0.1]}},
    "lights": [{"type": "point", "position": [0, 2, 4], "intensity": 20}],
    "objects": [{"type": "quad", "material": "m",
                 "corners": [[-3,-1,0],[0.5,-1,0],[0.5,1,0],[-3,1,0]]}]})";
  return loadScene(path);
}

GLint integer(GLenum name) {
  GLint value = -1;
  gl::glGetIntegerv(name, &value);
  return value;
}

// The state render() leaves (engine/gl/forward_renderer.h), read right after it returns.
void expectLeftState() {
  EXPECT_FALSE(gl::glIsEnabled(GL_DEPTH_TEST)) << "the reversed-Z depth test is the renderer's";
  EXPECT_EQ(integer(GL_DEPTH_FUNC), GL_LESS);
  EXPECT_EQ(integer(GL_DEPTH_WRITEMASK), GL_TRUE);
  EXPECT_FALSE(gl::glIsEnabled(GL_BLEND));
  EXPECT_EQ(integer(GL_BLEND_SRC_RGB), GL_ONE);
  EXPECT_EQ(integer(GL_BLEND_DST_RGB), GL_ZERO);
  EXPECT_FALSE(gl::glIsEnabled(GL_SCISSOR_TEST));
  EXPECT_FALSE(gl::glIsEnabled(GL_CULL_FACE));
  EXPECT_FALSE(gl::glIsEnabled(GL_CLIP_DISTANCE0));
  EXPECT_EQ(integer(GL_CLIP_ORIGIN), GL_LOWER_LEFT);
  EXPECT_EQ(integer(GL_CLIP_DEPTH_MODE), GL_ZERO_TO_ONE);
  EXPECT_EQ(integer(GL_DRAW_FRAMEBUFFER_BINDING), 0);
  EXPECT_EQ(integer(GL_VERTEX_ARRAY_BINDING), 0);
}

std::vector<float> render(RenderWorld& world, bool depthWrite, int w, int h) {
  auto& renderer = world.glCached<gl::ForwardRenderer>();
  const gl::Texture color = gl::Texture::create2D(gl::TextureFormat::RGBA32F, w, h);
  const gl::Texture depth = gl::Texture::create2D(gl::TextureFormat::D32F, w, h);
  gl::ForwardOptions options;
  options.depthWrite = depthWrite;  // false: the background is drawn first
  renderer.render(world.forwardScene(), gl::cameraView(world.scene().camera, float(w) / float(h)),
                  color, depth, options);
  expectLeftState();
  return gl::readTextureFloats(color);
}

TEST(ForwardRenderer, BackgroundDrawnAfterTheMeshesGivesTheImageOfBackgroundFirst) {
  const Scene scene = quadOverSky();
  RenderWorld world(scene, &gl::testing::osmesaContext());
  const int w = 64, h = 48;
  const std::vector<float> last = render(world, true, w, h);
  const std::vector<float> first = render(world, false, w, h);
  EXPECT_EQ(last, first);

  // Neither order may lose the quad or the sky: both are in the image, each where it belongs.
  int sky = 0, quad = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float* t = &last[(std::size_t(y) * w + x) * 4];
      const bool isSky = t[0] == 0.2f && t[1] == 0.4f && t[2] == 0.8f;
      sky += isSky ? 1 : 0;
      quad += !isSky && t[0] > t[2] ? 1 : 0;  // the orange quad, lit
      EXPECT_EQ(t[3], 1.f) << "every pixel is written: quad or sky (" << x << ", " << y << ")";
    }
  EXPECT_GT(sky, w * h / 4);
  EXPECT_GT(quad, w * h / 4);
  EXPECT_EQ(sky + quad, w * h);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
