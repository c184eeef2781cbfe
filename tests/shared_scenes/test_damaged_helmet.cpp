// DamagedHelmet.glb as `diptych render FILE` shows it with no options (docs/materials.md): the
// file has no light and no environment, so the program adds the default lighting; the helmet is
// then lit (not only its emissive parts), and its normal map changes the shading normals.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "engine/rt/rt_scene.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/default_lighting.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

const std::filesystem::path kHelmet =
    std::filesystem::path(DIPTYCH_SHARED_SCENES) / "damaged-helmet" / "DamagedHelmet.glb";
constexpr int kW = 96, kH = 96;

// Mean Rec. 709 luminance of the central half (in each axis) of the image, where the helmet is.
double centralMean(const CpuImage& s) {
  double sum = 0;
  int n = 0;
  for (int y = kH / 4; y < 3 * kH / 4; ++y)
    for (int x = kW / 4; x < 3 * kW / 4; ++x, ++n)
      sum += 0.2126 * s.f(x, y, 0) + 0.7152 * s.f(x, y, 1) + 0.0722 * s.f(x, y, 2);
  return sum / n;
}

TEST(DamagedHelmet, DefaultLightingLightsItAndTheNormalMapIsUsed) {
  if (!std::filesystem::exists(kHelmet)) GTEST_SKIP() << "no " << kHelmet;
  Scene scene = loadScene(kHelmet);
  ASSERT_TRUE(sceneIsUnlit(scene));
  auto unlit = testing::renderHybridFrame(scene, kW, kH, {"shade.color"});
  const double unlitMean = centralMean(unlit->output("shade.color"));

  ASSERT_TRUE(applyLighting(scene, testing::cameraOf(scene), {}));
  auto lit = testing::renderHybridFrame(scene, kW, kH, {"shade.color"});
  const double litMean = centralMean(lit->output("shade.color"));
  std::printf("[helmet] central mean luminance: file as is %.4f, default lighting %.4f\n",
              unlitMean, litMean);
  EXPECT_GT(litMean, 0.1);
  EXPECT_GT(litMean, 3.0 * unlitMean);

  // Normal map: along central primary rays, the shading normal departs from the interpolated
  // vertex normal by more than 5 degrees at some hits (panel seams, rivets: about 3 % of the
  // central hits; most of the map is flat). Ignoring the map gives none.
  const Material& m = scene.material(scene.meshes.at(0).material);
  ASSERT_GE(m.normalTexture, 0);
  const WorldGeometry world = flattenScene(scene);
  ASSERT_FALSE(world.meshes.at(0).tangents.empty());
  RtDevice device;
  RtScene rt(device, world);
  const Camera camera = testing::cameraOf(scene);
  int hits = 0, perturbed = 0;
  for (int y = kH / 4; y < 3 * kH / 4; y += 2)
    for (int x = kW / 4; x < 3 * kW / 4; x += 2) {
      const Ray r = primaryRay(camera, kW, kH, float(x) + 0.5f, float(y) + 0.5f);
      const auto hit = rt.intersect(r, 0.f, 1e30f);
      if (!hit) continue;
      const SurfacePoint s = makeSurfacePoint(
          scene, world, {hit->instance, hit->primitive, hit->u, hit->v}, r.direction);
      vec3 smooth = interpolateNormal(world.meshes[hit->instance], hit->primitive, hit->u, hit->v);
      if (!s.frontFacing) smooth = -smooth;
      ++hits;
      perturbed += glm::dot(glm::normalize(smooth), s.shadingNormal) < std::cos(glm::radians(5.f));
    }
  std::printf("[helmet] %d of %d central hits have a normal-mapped normal > 5 deg off\n", perturbed,
              hits);
  ASSERT_GT(hits, 100);
  EXPECT_GT(perturbed, hits / 100);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
