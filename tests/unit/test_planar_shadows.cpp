// planar_shadows (the lecture's brute-force shadow polygons projected onto planar receivers):
// on the ground plane it finds the shadows rt_shadows finds, casts nothing from what lies
// beyond the light or behind the plane, and leaves every non-planar surface lit.
#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "engine/shading/shadow_projection.h"
#include "passes/raster/planar_shadows.h"
#include "passes/slots.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

struct VisibilityPair {
  int groundPixels = 0, exactShadow = 0, planarShadow = 0, mismatched = 0, litElsewhere = 0,
      otherPixels = 0;
};

// Light 0's visibility from planar_shadows and rt_shadows on one frame each; the ground is
// instance 0 (the scene's first object).
VisibilityPair compareWithRtShadows(const std::filesystem::path& file, int w, int h) {
  Recipe recipe = defaultHybridRecipe();
  applySlotOverride(recipe, parseSlotOverride("visibility=planar_shadows"), builtinPasses());
  auto planar = diptych::testing::renderHybridFrame(file, w, h,
                                                    {"shadows.visibility", "gbuffer.hits"}, recipe);
  auto exact = diptych::testing::renderHybridFrame(file, w, h, {"shadows.visibility"});
  const CpuImage& hits = planar->output("gbuffer.hits");
  const CpuImage& vp = planar->output("shadows.visibility");
  const CpuImage& ve = exact->output("shadows.visibility");
  VisibilityPair r;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float p = vp.f(x, y, 0, 0), e = ve.f(x, y, 0, 0);
      if (hits.u(x, y, 0) != 1u) {
        r.otherPixels += hits.u(x, y, 0) != 0u;
        r.litElsewhere += hits.u(x, y, 0) != 0u && p == 1.f;
        continue;
      }
      EXPECT_TRUE(p == 0.f || p == 1.f) << x << "," << y;
      ++r.groundPixels;
      r.exactShadow += e < 0.5f;
      r.planarShadow += p < 0.5f;
      r.mismatched += (e < 0.5f) != (p < 0.5f);
    }
  return r;
}

std::filesystem::path writeScene(const std::string& name, const std::string& lights,
                                 const std::string& spheres) {
  const auto path = diptych::testing::scratchDir("diptych_planar_shadows") / (name + ".json");
  std::ofstream(path) << R"({"camera": {"position": [0, 12, 8], "target": [0, 0, -1], "fov": 50},
    "environment": {"color": [0, 0, 0]},
    "materials": {"m": {"color": [0.8, 0.8, 0.8], "kd": 1}},
    "lights": [)" << lights
                      << R"(],
    "objects": [{"type": "plane", "name": "ground", "size": [40, 40], "material": "m"})"
                      << spheres << "]}";
  return path;
}

std::string sphere(float x, float y, float z, float r) {
  return R"(, {"type": "sphere", "radius": )" + std::to_string(r) +
         R"(, "segments": [128, 64], "material": "m", "transform": {"translate": [)" +
         std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) + "]}}";
}

TEST(PlanarShadows, ProjectedPointLiesOnThePlaneAlongTheLightRay) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-3.f, 3.f);
  const vec4 plane(glm::normalize(vec3(0.2f, 1.f, -0.3f)), 0.5f);
  for (const vec4 light : {vec4(1.f, 6.f, 2.f, 1.f), vec4(0.3f, 1.f, 0.1f, 0.f)}) {
    for (int i = 0; i < 100; ++i) {
      const vec3 x(u(rng), u(rng), u(rng));
      const vec4 h = shading::shadowProjectedPoint(plane, light, x);
      ASSERT_NE(h.w, 0.f);
      const vec3 q = vec3(h) / h.w;
      EXPECT_NEAR(glm::dot(vec3(plane), q) + plane.w, 0.f, 1e-4f);
      // q, x and the light on one line: for a point light the segment's direction, for a
      // directional one the light's direction.
      const vec3 along = light.w == 1.f ? vec3(light) - x : vec3(light);
      EXPECT_LT(glm::length(glm::cross(q - x, along)), 1e-3f * (1.f + glm::length(q - x)));
    }
  }
}

TEST(PlanarShadows, ACasterAtTheLightsHeightStaysOnItsLine) {
  // cornell.json: the emissive quad around the area light's centre (y = 548.7) seen from the
  // back wall (z = 559.2). Its points project onto the wall's line y = 548.7, ever farther as
  // they near the light's depth; the shadow matrix as printed lost that line there (and drew a
  // wide polygon on the wall), the well-conditioned form keeps it to the float.
  const vec4 wall(0.f, 0.f, -1.f, 559.2f);  // oriented toward the light
  const vec4 light(278.f, 548.7f, 279.5f, 1.f);
  for (const float z : {332.f, 300.f, 281.f, 279.6f, 279.51f}) {
    const vec4 h = shading::shadowProjectedPoint(wall, light, vec3(213.f, 548.7f, z));
    ASSERT_GT(h.w, 0.f) << z;
    EXPECT_EQ(h.y / h.w, 548.7f) << z;
    EXPECT_NEAR(h.z / h.w, 559.2f, 1e-3f * std::abs(h.x / h.w)) << z;
  }
}

TEST(PlanarShadows, FindsTheSphereShadowDiscOnTheGround) {
  const auto file = std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/shadow-sphere.json";
  const VisibilityPair r = compareWithRtShadows(file, 96, 72);
  ASSERT_GT(r.groundPixels, 1000);
  EXPECT_GT(r.exactShadow, 50);
  // The rasterizer's sphere is a 256 x 128 tessellation of the traced one: its shadow may differ
  // at the disc's edge (0 pixels of 388 here).
  EXPECT_LE(r.mismatched, r.exactShadow / 20) << r.planarShadow << " vs " << r.exactShadow;
  // The ball is no planar receiver: lit everywhere, though rt_shadows darkens its lower half.
  EXPECT_GT(r.otherPixels, 100);
  EXPECT_EQ(r.litElsewhere, r.otherPixels);
}

TEST(PlanarShadows, CastsNothingFromBeyondThePointLightOrBehindThePlane) {
  // Only the sphere between the ground and the light shades the ground. Projected without the
  // slab clip, the sphere above the light would cast a shadow through the light at x ~ -2 and
  // the one under the ground one at x ~ 1.8 (94 wrong pixels against 0 with it).
  const auto file =
      writeScene("slab", R"({"type": "point", "position": [0, 3, 0], "intensity": 30})",
                 sphere(0, 1.5f, -2, 0.5f) + sphere(2, 6, 0, 1) + sphere(3, -2, 0, 1));
  const VisibilityPair r = compareWithRtShadows(file, 160, 120);
  ASSERT_GT(r.groundPixels, 5000);
  EXPECT_GT(r.exactShadow, 100);
  EXPECT_LE(r.mismatched, r.exactShadow / 20) << r.planarShadow << " vs " << r.exactShadow;
}

TEST(PlanarShadows, DirectionalLightsProjectAlongTheirDirection) {
  const auto file = writeScene(
      "directional", R"({"type": "directional", "direction": [0.4, -1, -0.3], "intensity": 2})",
      sphere(0, 1.5f, -1, 1) + sphere(-3, 2.5f, 1, 0.7f));
  const VisibilityPair r = compareWithRtShadows(file, 96, 72);
  ASSERT_GT(r.groundPixels, 1000);
  EXPECT_GT(r.exactShadow, 50);
  EXPECT_LE(r.mismatched, r.exactShadow / 20) << r.planarShadow << " vs " << r.exactShadow;
}
}  // namespace DIPTYCH_UNITY_ID
