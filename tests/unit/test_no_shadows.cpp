// no_shadows (the visibility slot with V_i = 1): its signal is 1 on every light's layer, and
// removing shadows only adds light: the shaded frame is >= the exact one at every pixel, equal
// where rt_shadows finds every light visible, and brighter somewhere in the shadow.
#include <gtest/gtest.h>

#include "passes/slots.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

TEST(NoShadows, LightsEveryPixelAndOnlyAddsLight) {
  const auto file = std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/shadow-sphere.json";
  constexpr int kW = 64, kH = 48;
  Recipe recipe = defaultHybridRecipe();
  applySlotOverride(recipe, parseSlotOverride("visibility=no_shadows"), builtinPasses());
  auto none = diptych::testing::renderHybridFrame(file, kW, kH,
                                                  {"shade.color", "shadows.visibility"}, recipe);
  auto exact =
      diptych::testing::renderHybridFrame(file, kW, kH, {"shade.color", "shadows.visibility"});

  const CpuImage& v = none->output("shadows.visibility");
  ASSERT_EQ(v.desc.layers, int(none->scene.lights.size()));
  for (int l = 0; l < v.desc.layers; ++l)
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) ASSERT_EQ(v.f(x, y, 0, l), 1.f) << x << "," << y;

  const CpuImage& unshadowed = none->output("shade.color");
  const CpuImage& shadowed = exact->output("shade.color");
  const CpuImage& exactV = exact->output("shadows.visibility");
  int brighter = 0, inShadow = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      bool lit = true, more = false;
      for (int l = 0; l < exactV.desc.layers; ++l) lit = lit && exactV.f(x, y, 0, l) == 1.f;
      for (int ch = 0; ch < 3; ++ch) {
        ASSERT_GE(unshadowed.f(x, y, ch), shadowed.f(x, y, ch)) << x << "," << y;
        more = more || unshadowed.f(x, y, ch) > shadowed.f(x, y, ch);
        // Where every light reaches the point, V = 1 either way: the same radiance, bit for bit.
        if (lit) {
          ASSERT_EQ(unshadowed.f(x, y, ch), shadowed.f(x, y, ch)) << x << "," << y;
        }
      }
      inShadow += lit ? 0 : 1;
      brighter += more ? 1 : 0;
    }
  EXPECT_GT(inShadow, 0);
  EXPECT_GT(brighter, 0);
}

}  // namespace DIPTYCH_UNITY_ID
