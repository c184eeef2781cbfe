// The hybrid frame's per-pixel CPU loops after issue 14's rework: CpuImage row views read and
// write exactly what f/setF do, and the state those loops keep across frames (rt_shadows'
// receiver arrays, shade's per-thread row scratch, the exact-hit buffer's storage) never leaks
// one frame into the next: a frame after a camera move equals a fresh render of that camera.
#include <gtest/gtest.h>

#include <cstring>

#include "engine/graph/cpu_image.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;
using namespace diptych::testing;

float valueAt(int x, int y, int c, int layer) {
  return float(x) + 0.25f * float(y) + 1000.f * float(c) - 7.f * float(layer);
}

bool sameWords(const CpuImage& a, const CpuImage& b) {
  return a.desc == b.desc && a.words == b.words;
}

TEST(CpuImageRows, RowViewsReadAndWriteWhatFAndSetFDo) {
  for (const Format format : {Format::R32F, Format::RG32F, Format::RGBA32F}) {
    CpuImage image({format, 5, 4, 3});
    const int channels = formatChannels(format);
    ASSERT_EQ(image.channels(), channels);
    for (int layer = 0; layer < 3; ++layer)
      for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x)
          for (int c = 0; c < channels; ++c) image.setF(x, y, c, valueAt(x, y, c, layer), layer);
    for (int layer = 0; layer < 3; ++layer) {
      for (int y = 0; y < 4; ++y) {
        const CpuFloatRow row(&image, y, layer);
        ASSERT_TRUE(row);
        for (int x = 0; x < 5; ++x)
          for (int c = 0; c < channels; ++c)
            EXPECT_EQ(row(x, c), image.f(x, y, c, layer)) << formatName(format);
        // Writing through row() lands where setF writes.
        image.row(y, layer)[4 * channels - 1] = std::bit_cast<std::uint32_t>(-1.5f);
        EXPECT_EQ(image.f(3, y, channels - 1, layer), -1.5f);
      }
    }
  }
  const CpuFloatRow none(nullptr, 0);
  EXPECT_FALSE(none);
  EXPECT_EQ(none(3, 2), 0.f);
  EXPECT_EQ(none.rgb(7), vec3(0.f));
}

TEST(HybridCpuLoops, AFrameAfterACameraMoveEqualsAFreshRenderOfThatCamera) {
  const auto file = std::filesystem::path(samplesDir()) / "scenes/whitted.json";
  const std::vector<std::string> outputs = {"shade.color", "shadows.visibility"};
  constexpr int kW = 96, kH = 72;
  auto moving = renderHybridFrame(file, kW, kH, outputs);
  // Closer to the spheres: more covered pixels, so every kept array must grow, and a different
  // set of them; then back to the first camera, so they shrink again.
  const Camera first = moving->graph.frame.camera;
  Camera closer = first;
  closer.position = first.target + 0.6f * (first.position - first.target);
  for (const Camera& camera : {closer, first}) {
    moving->graph.frame.camera = camera;
    moving->context->makeCurrent();  // the fresh frames below make their own context current
    moving->executor->runFrame();
    Scene scene = loadScene(file);
    scene.camera = camera;
    scene.hasCamera = true;
    auto fresh = renderHybridFrame(std::move(scene), kW, kH, outputs);
    for (const std::string& name : outputs)
      EXPECT_TRUE(sameWords(moving->output(name), fresh->output(name)))
          << name << " after the camera moved differs from a fresh render";
  }
  // The two cameras really give different frames (the comparison above could not pass by luck).
  auto reference = renderHybridFrame(file, kW, kH, outputs);
  moving->graph.frame.camera = closer;
  moving->context->makeCurrent();
  moving->executor->runFrame();
  EXPECT_FALSE(sameWords(moving->output("shade.color"), reference->output("shade.color")));
}
}  // namespace DIPTYCH_UNITY_ID
