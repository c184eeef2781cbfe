// The shared AlphaBlendModeTest.glb (MASK materials with cutoffs 0.25, 0.5 and 0.75 on one
// textured alpha gradient, plus BLEND and OPAQUE) under an added point light: both visibility
// producers run on it without GL or Embree errors, every masked material is alpha-tested on
// both sides, and the shadow map agrees with the shadow rays outside the 2-pixel band around
// the exact shadow boundaries.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "engine/gl/debug.h"
#include "engine/gl/shading_buffers.h"
#include "engine/scene/load.h"
#include "tests/support/lit_model.h"
#include "tests/support/test_paths.h"
#include "tests/unit/shadow_map_compare.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

TEST(AlphaMaskGltf, AlphaBlendModeTestRendersThroughBothProducers) {
  const std::filesystem::path file =
      std::filesystem::path(DIPTYCH_SHARED_SCENES) / "alpha-blend-mode-test/AlphaBlendModeTest.glb";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not present";
  Scene scene = loadScene(file);
  int masked = 0;
  for (const Material& m : scene.materials) masked += m.alphaMode == AlphaMode::Mask;
  EXPECT_EQ(masked, 3);
  // The file has no lights: a point light above the scene's centre, in front of the tests.
  testing::addTestLight(scene);

  {
    RenderWorld world(scene, &gl::testing::osmesaContext());
    EXPECT_EQ(world.rtScene().alphaMaskedGeometries(), 3);
    EXPECT_TRUE(world.glShading().anyAlphaTested());
    for (int m = 0; m < int(scene.materials.size()); ++m) {
      const bool tested = world.glShading().alphaDraw(m) == gl::AlphaDraw::AlphaTested;
      EXPECT_EQ(tested, scene.materials[std::size_t(m)].alphaMode == AlphaMode::Mask)
          << scene.materials[std::size_t(m)].name;
    }
  }

  // The receiver: the instance of the bed the test objects stand on (material "MatBed").
  int bed = -1;
  for (int i = 0; i < int(scene.instances.size()); ++i) {
    const Mesh& mesh = scene.meshes[std::size_t(scene.instances[std::size_t(i)].mesh)];
    if (scene.material(mesh.material).name == "MatBed") bed = i;
  }
  ASSERT_GE(bed, 0);
  const int errors = gl::glDebugErrorCount();
  const testing::ShadowComparison c =
      testing::compareShadows(scene, {{"resolution", 2048}, {"bias", "slope"}}, bed);
  EXPECT_EQ(gl::glDebugErrorCount(), errors);
  EXPECT_TRUE(c.finiteInUnitRange);
  std::printf(
      "AlphaBlendModeTest: %zu bed pixels outside the band, misclassified %.2f%% "
      "(false shadow %zu, false lit %zu)\n",
      c.considered, 100.0 * c.misclassified(), c.falseShadow, c.falseLit);
  EXPECT_GT(c.considered, 1000u);
  EXPECT_LT(c.misclassified(), 0.05);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
