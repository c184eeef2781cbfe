// WhittedTracer::direct traces a light's shadow rays only where the material's response to the
// light is not zero (engine/rt/whitted.cpp; pbrt-v4's SampleLd order). Counted here with the
// tracer's own ray counter and its observer of RAYTRACING calls: the image cannot show the
// skip (V_i S_i 0 = 0 either way), the number of rays can.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/graph/render_world.h"
#include "engine/rt/whitted.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/load.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

// An analytic unit sphere at the origin seen from z = 5; one point light at (0, 0, lightZ).
Scene sphereScene(const std::string& material, float lightZ) {
  const auto dir = ::diptych::testing::scratchDir("diptych_whitted_shadow_skip");
  std::filesystem::create_directories(dir);
  const auto path = dir / "scene.json";
  std::ofstream(path) << R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov": 40},
    "ambient": [0.05, 0.05, 0.05],
    "materials": {"m": )" + material +
                             R"(},
    "lights": [{"type": "point", "position": [0, 0, )" +
                             std::to_string(lightZ) + R"(], "intensity": 50}],
    "objects": [{"type": "sphere", "radius": 1, "geometry": "analytic", "material": "m"}]})";
  return loadScene(path);
}

struct Counts {
  std::uint64_t rays = 0;  // tracer.raysTraced(): RAYTRACING calls + shadow rays
  int primaries = 0, hits = 0;
};

Counts trace(const Scene& scene) {
  RenderWorld world(scene);
  WhittedTracer tracer(scene, world.geometry(), world.rtScene(), {5, 1});
  std::atomic<int> hits{0};
  tracer.setRayObserver([&](const RayTreeEvent& e) { hits += e.hit ? 1 : 0; });
  const int w = 32, h = 24;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      tracer.radiance(primaryRay(scene.camera, w, h, float(x) + 0.5f, float(y) + 0.5f), 1,
                      std::uint32_t(y * w + x));
  return {tracer.raysTraced(), w * h, hits.load()};
}

TEST(WhittedShadowSkip, ADiffuseSurfaceFacingTheLightTracesOneShadowRayPerHit) {
  const Counts c = trace(sphereScene(R"({"kd": 1})", 10.f));
  ASSERT_GT(c.hits, 100);
  EXPECT_EQ(c.rays, std::uint64_t(c.primaries + c.hits));
}

TEST(WhittedShadowSkip, NoResponseMeansNoShadowRays) {
  // k_a = k_d = k_s = 0: DIRECTA is 0 everywhere, so no hit needs to know its visibility.
  const Counts c = trace(sphereScene(R"({"kd": 0, "ks": 0})", 10.f));
  ASSERT_GT(c.hits, 100);
  EXPECT_EQ(c.rays, std::uint64_t(c.primaries));
}

TEST(WhittedShadowSkip, ALightBehindTheVisibleSideNeedsNoShadowRays) {
  // The light behind the sphere: every visible point has n.l <= 0, so DIRECTA (k_a = 0) is 0.
  const Counts c = trace(sphereScene(R"({"kd": 1, "ks": 0.5})", -10.f));
  ASSERT_GT(c.hits, 100);
  EXPECT_EQ(c.rays, std::uint64_t(c.primaries));
}
}  // namespace DIPTYCH_UNITY_ID
