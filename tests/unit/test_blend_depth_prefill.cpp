// The blend producers' depth pre-fill (sorted_blend / unsorted_blend, param depth_prefill,
// passes/raster/blend_transmission.cpp): the first-surface step writes the forward passes' depth
// (near where the first surface does not transmit) so that the early depth test rejects what
// forward.frag would discard. It must not change a bit of the transmission signal: checked
// against the old path (depth_prefill = false) on whitted (one glass sphere) and on techniques
// (two overlapping tinted glass objects), at a size where both have mask-zeroed and kept pixels
// inside the blend's scissor. The first-surface step is a full-screen draw that writes depth: it
// must leave the GL state of every full-screen draw (passes/raster/fullscreen_resolve.h).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "engine/gl/loader.h"
#include "engine/gl/transfer.h"
#include "engine/graph/executor.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/raster/blend_transmission.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kWidth = 200, kHeight = 150;

CpuImage blendSignal(const Scene& scene, const std::string& type, bool prefill) {
  Recipe recipe;
  recipe.passes = {{.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
                   {.name = "blend",
                    .type = type,
                    .params = {{"depth_prefill", prefill}},
                    .inputs = {{"hits", "gbuffer.hits"}},
                    .place = "passes[1]"}};
  recipe.outputs = {"blend.transmission"};
  const CompiledGraph graph =
      compileGraph(recipe, builtinPasses(), scene, {kWidth, kHeight, scene.camera});
  RenderWorld world(scene, &gl::testing::osmesaContext());
  GraphExecutor executor(graph, world);
  executor.runFrame();
  return executor.output("blend.transmission");
}

void expectSameBits(const std::string& sceneFile, const std::string& type) {
  const Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / sceneFile);
  const CpuImage before = blendSignal(scene, type, false);
  const CpuImage after = blendSignal(scene, type, true);
  ASSERT_EQ(before.desc.width, kWidth);
  ASSERT_EQ(after.desc.width, kWidth);
  int kept = 0, zeroed = 0, differing = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      bool nonzero = false;
      for (int c = 0; c < 3; ++c) {
        const float a = before.f(x, y, c), b = after.f(x, y, c);
        if (std::memcmp(&a, &b, sizeof a) != 0) ++differing;
        nonzero = nonzero || a != 0.f;
      }
      ++(nonzero ? kept : zeroed);
    }
  EXPECT_EQ(differing, 0) << sceneFile << " " << type;
  // Both kinds of pixel occur, or the comparison would not cover what the pre-fill changes.
  EXPECT_GT(kept, 100) << sceneFile;
  EXPECT_GT(zeroed, 100) << sceneFile;
}

TEST(BlendDepthPrefill, SortedBlendSameBitsOnWhitted) {
  expectSameBits("scenes/whitted.json", "sorted_blend");
}

TEST(BlendDepthPrefill, SortedAndUnsortedSameBitsWithOverlappingGlass) {
  expectSameBits("scenes/techniques.json", "sorted_blend");
  expectSameBits("scenes/techniques.json", "unsorted_blend");
}

TEST(BlendDepthPrefill, FirstSurfaceStepWritesDepthAndLeavesTheFullscreenState) {
  const Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  RenderWorld world(scene, &gl::testing::osmesaContext());
  constexpr int w = 16, h = 8;
  // No hit anywhere: every pixel's first surface is the background, which does not transmit.
  const gl::Texture hits = gl::Texture::create2D(gl::TextureFormat::RGBA32UI, w, h);
  gl::uploadTexture(hits, std::vector<std::uint32_t>(4 * w * h, 0u));
  const gl::Texture first = gl::Texture::create2D(gl::TextureFormat::RGBA32F, w, h);
  const gl::Texture depth = gl::Texture::create2D(gl::TextureFormat::D32F, w, h);
  gl::uploadTextureFloats(depth, std::vector<float>(w * h, 0.5f));
  // A depth state unlike the contract's, so that a draw which keeps or leaks state shows.
  gl::glEnable(GL_DEPTH_TEST);
  gl::glDepthFunc(GL_GREATER);
  gl::glDepthMask(GL_FALSE);
  renderBlendFirst(world, hits, nullptr, scene.camera.position, first, glm::ivec4(0, 0, w, h),
                   &depth);
  for (float d : gl::readTextureFloats(depth)) ASSERT_EQ(d, 1.f);  // "near": not transmissive
  GLint func = 0, mask = 0;
  gl::glGetIntegerv(GL_DEPTH_FUNC, &func);
  gl::glGetIntegerv(GL_DEPTH_WRITEMASK, &mask);
  EXPECT_FALSE(gl::glIsEnabled(GL_DEPTH_TEST));
  EXPECT_EQ(func, GL_LESS);
  EXPECT_EQ(mask, GL_TRUE);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
