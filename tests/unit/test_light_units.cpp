// KHR_lights_punctual photometric units (docs/materials.md, "Light units") on the Blender-like
// sample samples/scenes/blender-point-light.gltf: a 3000 W point light 8 m above a ground plane
// of base colour 0.8, exported as Blender's exporter does (cd = W / (4 pi) * 683).
//
// Prediction for a Lambertian plane of albedo rho under a point light of I W/sr (what Blender
// renders): L = rho / pi * I cos(theta) / d^2, with I = cd / 683. The test renders the plane
// alone (spheres removed, so nothing shadows it) through the default hybrid frame and compares
// the mean over plane pixels with the mean of the prediction at the same pixels (the plane point
// found analytically from the pixel's primary ray). The glossy term (k_s = 0.04 at roughness 1)
// is part of the render and not of the prediction: it adds a few per cent.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "engine/scene/load.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

const std::filesystem::path kSample =
    std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes" / "blender-point-light.gltf";
constexpr double kPi = 3.14159265358979;
constexpr double kCandela = 3000.0 / (4.0 * kPi) * 683.0;  // what the file holds

TEST(LightUnits, CandelaBecomeShadingUnitsBy683Pi) {
  const Scene scene = loadScene(kSample);
  ASSERT_EQ(scene.lights.size(), 1u);
  const Light& l = scene.lights[0];
  EXPECT_EQ(l.type, LightType::Point);
  EXPECT_NEAR(l.intensity, kCandela / (683.0 * kPi), 1e-4 * l.intensity);
  EXPECT_NEAR(l.position.y, 8.f, 1e-5f);
}

TEST(LightUnits, BlenderPointLightPlaneRadianceMatchesPhotometricPrediction) {
  Scene scene = loadScene(kSample);
  std::erase_if(scene.instances, [](const Instance& i) { return i.name != "Plane"; });
  ASSERT_EQ(scene.instances.size(), 1u);
  constexpr int kW = 96, kH = 72;
  auto f = testing::renderHybridFrame(scene, kW, kH, {"shade.color"});
  const CpuImage& color = f->output("shade.color");
  const Camera camera = testing::cameraOf(f->scene);
  const vec3 light = f->scene.lights[0].position;
  const double intensityWattsPerSr = kCandela / 683.0;
  double measured = 0, predicted = 0, peak = 0;
  int pixels = 0, saturated = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const Ray r = primaryRay(camera, kW, kH, float(x) + 0.5f, float(y) + 0.5f);
      if (!(r.direction.y < 0.f)) continue;  // sky
      const vec3 p = r.origin + r.direction * (-r.origin.y / r.direction.y);
      if (std::abs(p.x) > 19.5f || std::abs(p.z) > 19.5f) continue;  // off the 40 m plane
      const vec3 toLight = light - p;
      const double d2 = glm::dot(toLight, toLight);
      const double cosTheta = toLight.y / std::sqrt(d2);
      predicted += 0.8 / kPi * intensityWattsPerSr * cosTheta / d2;
      const double lum =
          0.2126 * color.f(x, y, 0) + 0.7152 * color.f(x, y, 1) + 0.0722 * color.f(x, y, 2);
      measured += lum;
      peak = std::max(peak, lum);
      saturated += color.f(x, y, 0) >= 1.f || color.f(x, y, 1) >= 1.f || color.f(x, y, 2) >= 1.f;
      ++pixels;
    }
  ASSERT_GT(pixels, kW * kH / 2) << "the plane should fill most of the frame";
  measured /= pixels;
  predicted /= pixels;
  std::printf(
      "[light units] %d plane pixels: mean radiance %.4f, predicted %.4f (ratio %.3f), "
      "peak %.3f\n",
      pixels, measured, predicted, measured / predicted, peak);
  EXPECT_NEAR(measured / predicted, 1.0, 0.2);
  EXPECT_EQ(saturated, 0) << "no plane pixel may reach 1 at exposure 0";
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
