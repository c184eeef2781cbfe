// The one full-screen draw (passes/raster/fullscreen_resolve.h) in each of its modes, with a
// real program on the test context: Test draws only where the triangle's depth 0 passes against
// the given depth and leaves that depth alone (GL shade's split), Write stores the program's
// gl_FragDepth (the blend producers' pre-fill), and every mode leaves the GL state of the
// header's contract, whatever state it found.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "engine/gl/loader.h"
#include "engine/gl/shader.h"
#include "engine/gl/transfer.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/raster/fullscreen_resolve.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

namespace fs = std::filesystem;

constexpr int kWidth = 8, kHeight = 4;

// uColor everywhere; with WRITE_DEPTH also gl_FragDepth = uDepth. Alpha is the viewport width
// the draw sets, so that a draw without it shows.
constexpr const char* kFragment = R"(
layout(location = 0) out vec4 outColor;
uniform vec4 uColor;
uniform float uDepth;
uniform vec2 uViewportSize;
void main() {
  outColor = vec4(uColor.rgb, uViewportSize.x);
#ifdef WRITE_DEPTH
  gl_FragDepth = uDepth;
#endif
}
)";

class FullscreenResolveTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("diptych_fullscreen_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    std::ofstream(dir_ / "constant.frag") << kFragment;
    color_ = gl::Texture::create2D(gl::TextureFormat::RGBA32F, kWidth, kHeight);
    depth_ = gl::Texture::create2D(gl::TextureFormat::D32F, kWidth, kHeight);
    clearToZero(color_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  FullscreenResolve resolve(bool writeDepth) {
    std::vector<gl::ShaderDefine> defines;
    if (writeDepth) defines.push_back({"WRITE_DEPTH", ""});
    return FullscreenResolve(gl::loadProgram(
        {gl::shaderDirectory() / "fullscreen.vert", dir_ / "constant.frag"}, defines));
  }

  const Scene scene_ = loadScene(fs::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  RenderWorld world_{scene_, &gl::testing::osmesaContext()};
  fs::path dir_;
  gl::Texture color_, depth_;
};

// Every piece of state the contract names set to something else.
void dirtyState() {
  gl::glClipControl(GL_UPPER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  gl::glEnable(GL_DEPTH_TEST);
  gl::glDepthFunc(GL_GREATER);
  gl::glDepthMask(GL_FALSE);
  gl::glEnable(GL_BLEND);
  gl::glBlendFunc(GL_ONE, GL_ONE);
  gl::glEnable(GL_SCISSOR_TEST);
  gl::glScissor(0, 0, 1, 1);
  gl::glEnable(GL_CULL_FACE);
  gl::glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
}

GLint integer(GLenum name) {
  GLint value = -1;
  gl::glGetIntegerv(name, &value);
  return value;
}

void expectContract(const char* mode) {
  SCOPED_TRACE(mode);
  EXPECT_FALSE(gl::glIsEnabled(GL_DEPTH_TEST));
  EXPECT_EQ(integer(GL_DEPTH_FUNC), GL_LESS);
  EXPECT_EQ(integer(GL_DEPTH_WRITEMASK), GL_TRUE);
  EXPECT_FALSE(gl::glIsEnabled(GL_BLEND));
  EXPECT_EQ(integer(GL_BLEND_SRC_RGB), GL_ONE);
  EXPECT_EQ(integer(GL_BLEND_DST_RGB), GL_ZERO);
  EXPECT_FALSE(gl::glIsEnabled(GL_SCISSOR_TEST));
  EXPECT_FALSE(gl::glIsEnabled(GL_CULL_FACE));
  GLint colorMask[4] = {0, 0, 0, 0};
  gl::glGetIntegerv(GL_COLOR_WRITEMASK, colorMask);
  for (GLint channel : colorMask) EXPECT_EQ(channel, GL_TRUE);
  EXPECT_EQ(integer(GL_CLIP_ORIGIN), GL_LOWER_LEFT);
  EXPECT_EQ(integer(GL_CLIP_DEPTH_MODE), GL_ZERO_TO_ONE);
  EXPECT_EQ(integer(GL_DRAW_FRAMEBUFFER_BINDING), 0);
  EXPECT_EQ(integer(GL_VERTEX_ARRAY_BINDING), 0);
}

TEST_F(FullscreenResolveTest, TestModeDrawsWhereTheDepthPassesAndKeepsIt) {
  // Left half the cleared "far" 0 (no surface), right half a surface at 0.25.
  std::vector<float> depth(kWidth * kHeight);
  for (int i = 0; i < kWidth * kHeight; ++i) depth[i] = i % kWidth < kWidth / 2 ? 0.f : 0.25f;
  gl::uploadTextureFloats(depth_, depth);
  FullscreenResolve background = resolve(false), surfaces = resolve(false);
  background.program().set("uColor", vec4(1.f, 0.f, 0.f, 0.f));
  surfaces.program().set("uColor", vec4(0.f, 1.f, 0.f, 0.f));
  dirtyState();
  background.draw(world_, color_,
                  {.depth = &depth_, .depthMode = FullscreenDepth::Test, .depthFunc = GL_GEQUAL});
  expectContract("test, GL_GEQUAL");
  dirtyState();
  surfaces.draw(world_, color_,
                {.depth = &depth_, .depthMode = FullscreenDepth::Test, .depthFunc = GL_LESS});
  expectContract("test, GL_LESS");

  const std::vector<float> color = gl::readTextureFloats(color_);
  for (int i = 0; i < kWidth * kHeight; ++i) {
    const bool sky = depth[i] == 0.f;
    EXPECT_EQ(color[4 * i + 0], sky ? 1.f : 0.f) << i;
    EXPECT_EQ(color[4 * i + 1], sky ? 0.f : 1.f) << i;
    EXPECT_EQ(color[4 * i + 3], float(kWidth)) << i;
  }
  EXPECT_EQ(gl::readTextureFloats(depth_), depth);  // tested, never written
}

TEST_F(FullscreenResolveTest, WriteModeStoresFragDepthInsideTheScissor) {
  gl::uploadTextureFloats(depth_, std::vector<float>(kWidth * kHeight, 0.5f));
  FullscreenResolve prefill = resolve(true);
  prefill.program().set("uColor", vec4(0.f, 0.f, 1.f, 0.f));
  prefill.program().set("uDepth", 0.75f);
  dirtyState();
  // GL's rows from the bottom: the scissor keeps columns 2..4 of the bottom two rows.
  prefill.draw(world_, color_, {.scissor = glm::ivec4(2, 0, 3, 2), .depth = &depth_});
  expectContract("write");

  const std::vector<float> depth = gl::readTextureFloats(depth_);
  const std::vector<float> color = gl::readTextureFloats(color_);
  for (int y = 0; y < kHeight; ++y)  // row 0 the top (transfer.h)
    for (int x = 0; x < kWidth; ++x) {
      const int i = y * kWidth + x;
      const bool inside = x >= 2 && x < 5 && y >= kHeight - 2;
      EXPECT_EQ(depth[i], inside ? 0.75f : 0.5f) << x << "," << y;
      EXPECT_EQ(color[4 * i + 2], inside ? 1.f : 0.f) << x << "," << y;
    }
}

TEST_F(FullscreenResolveTest, ColourModesLeaveTheContractState) {
  FullscreenResolve constant = resolve(false);
  constant.program().set("uColor", vec4(0.5f, 0.5f, 0.5f, 0.f));
  dirtyState();
  constant.draw(world_, color_);
  expectContract("plain");
  dirtyState();
  constant.draw(world_, color_, {.multiply = true});
  expectContract("multiply");
  // 0.5 written, then multiplied by 0.5 (dst * src).
  const std::vector<float> color = gl::readTextureFloats(color_);
  for (int i = 0; i < kWidth * kHeight; ++i) EXPECT_EQ(color[4 * i], 0.25f) << i;
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
