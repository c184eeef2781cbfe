// Issue 9: TextureSettingsTest.glb's "single-sided" row. Its Test cell holds a single-sided
// polygon turned away from the camera with a red X, in front of a green check: glTF's
// doubleSided false culls the polygon, so the cell shows the check, as its Sample-pass cell
// does. Before the rule the X showed on both sides of the engine.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "engine/graph/recipe.h"
#include "engine/scene/default_lighting.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kW = 240, kH = 180;

// Mean of green minus red over a pixel rectangle [x0, x1) x [y0, y1): positive where a green
// check on white shows, negative where a red X on white does (white has g == r).
float greenOverRed(const CpuImage& image, int x0, int x1, int y0, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) sum += double(image.f(x, y, 1)) - double(image.f(x, y, 0));
  return float(sum / double((x1 - x0) * (y1 - y0)));
}

TEST(SingleSidedGltf, TextureSettingsTestSingleSidedCellShowsTheCheck) {
  const std::filesystem::path file = std::filesystem::path(DIPTYCH_SHARED_SCENES) /
                                     "texture-settings-test/TextureSettingsTest.glb";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not present";
  Scene scene = loadScene(file);
  int singleSided = 0;
  for (const Material& m : scene.materials) singleSided += m.doubleSided ? 0 : 1;
  EXPECT_GT(singleSided, 0);
  // What `diptych render` adds to this unlit file (the procedural sky and sun).
  applyLighting(scene, testing::cameraOf(scene), {});
  const std::string raster =
      (std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "graphs" / "raster.json").string();
  for (const auto& [name, recipe] :
       {std::pair<std::string, Recipe>{"hybrid", defaultHybridRecipe()},
        std::pair<std::string, Recipe>{"raster", loadRecipe(raster)}}) {
    auto f = testing::renderHybridFrame(scene, kW, kH, {"shade.color"}, recipe);
    const CpuImage& image = f->output("shade.color");
    // The row's two cells at this size (read from a render): Test, then Sample pass.
    const float test = greenOverRed(image, 122, 128, 54, 60);
    const float sample = greenOverRed(image, 145, 151, 54, 60);
    EXPECT_GT(sample, 0.05f) << name << ": the Sample-pass cell is a green check";
    // The check lies in the culled polygon's shadow (shadow rays see both sides): dimmer, so a
    // lower bar; the red X on white (the polygon not culled) gives a negative mean.
    EXPECT_GT(test, 0.02f) << name << ": the Test cell must show the check, not the red X";
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
