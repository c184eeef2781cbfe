// The design's standing consistency test (tests/unit/test_reference_consistency.cpp) on the
// shared glTF models: the built-in hybrid recipe, every slot exact, against rt_whitted in the same
// frame, over the pixels whose primary hit the two agree on. It found LightsPunctualLamp's shade
// missing from the hybrid: its material has transmission factor 1, metallic factor 1 and a
// metallic-roughness texture whose texels make it a dielectric, and the compiler culled
// rt_transmission ("scene has no transmissive materials") from the factors alone.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "engine/scene/default_lighting.h"
#include "passes/common/hits_texel.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kW = 128, kH = 96;

class GltfReferenceConsistency : public ::testing::TestWithParam<const char*> {};

TEST_P(GltfReferenceConsistency, AllExactHybridMatchesWhitted) {
  const std::filesystem::path file = std::filesystem::path(DIPTYCH_SHARED_SCENES) / GetParam();
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no " << file;
  Scene scene = loadScene(file);
  applyLighting(scene, testing::cameraOf(scene), {});  // as `diptych render` lights it
  Recipe recipe = defaultHybridRecipe();
  recipe.passes.push_back({.name = "reference", .type = "rt_whitted", .place = "test"});
  const auto f = testing::renderHybridFrame(
      std::move(scene), kW, kH, {"shade.color", "reference.color", "gbuffer.hits"}, recipe);
  const CpuImage& hybrid = f->output("shade.color");
  const CpuImage& reference = f->output("reference.color");
  const CpuImage& gbuffer = f->output("gbuffer.hits");
  const RtScene& rt = f->world->rtScene();
  const Camera& camera = f->graph.frame.camera;
  double num = 0, den = 0;
  int agreed = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const Ray ray = primaryRay(camera, kW, kH, x + 0.5f, y + 0.5f);
      const auto traced = rt.intersect(ray, 0.f, std::numeric_limits<float>::infinity());
      const auto raster =
          exactTexel(gbuffer, f->world->geometry(), camera, x, y, &f->world->rtScene());
      // Coverage and triangle must agree (silhouettes and shared edges may not), and the traced
      // hit must be of a non-culled face: the single-sided culling is tested elsewhere.
      if (!traced || !raster || traced->instance != raster->instance ||
          traced->primitive != raster->primitive)
        continue;
      ++agreed;
      for (int c = 0; c < 3; ++c) {
        const double h = hybrid.f(x, y, c), r = reference.f(x, y, c);
        num += (h - r) * (h - r);
        den += r * r;
      }
    }
  const double relativeRmse = den > 0 ? std::sqrt(num / den) : 0.0;
  std::printf("%s: relative RMSE %.3g over %d agreed pixels\n", GetParam(), relativeRmse, agreed);
  ASSERT_GT(agreed, kW * kH / 50);
  EXPECT_LT(relativeRmse, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Models, GltfReferenceConsistency,
                         ::testing::Values("lights-punctual-lamp/LightsPunctualLamp.gltf",
                                           "damaged-helmet/DamagedHelmet.glb",
                                           "transmission-test/TransmissionTest.glb",
                                           "attenuation-test/AttenuationTest.glb",
                                           "glass-vase-flowers/GlassVaseFlowers.glb",
                                           "texture-sampler-assetgen/Texture_Sampler_00.gltf"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::filesystem::path(info.param).stem().string();
                         });

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
