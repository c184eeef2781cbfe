// The blend producers' depth pre-fill (sorted_blend / unsorted_blend, param depth_prefill,
// passes/raster/blend_transmission.cpp): the first-surface step writes the forward passes' depth
// (near where the first surface does not transmit) so that the early depth test rejects what
// forward.frag would discard. It must not change a bit of the transmission signal: checked
// against the old path (depth_prefill = false) on whitted (one glass sphere) and on techniques
// (two overlapping tinted glass objects), at a size where both have mask-zeroed and kept pixels
// inside the blend's scissor.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "engine/graph/executor.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace {

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

}  // namespace
}  // namespace diptych
