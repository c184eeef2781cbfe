// pbrt-style reintersection test (pbrt-v4's "Triangle, Reintersect" test, here against Embree):
// random triangles of log-uniform size 1e-6 .. 1e6 at log-uniform distance 1e-6 .. 1e6 from the
// origin (kept where the float vertices still resolve the triangle: size >= 1e-4 x distance),
// random points on them, and secondary rays leaving in random directions of either hemisphere
// (reflected: offset to the front, transmitted: to the back) from offsetRayOrigin. A ray that
// leaves a flat triangle can never meet it again, so every hit of its own triangle is a
// self-intersection ("miss" of the offset). Bound: zero, at kRelativeOffset = 256 FLT_EPSILON.
// The same trial with smaller constants is printed to show the margin (docs/numerics.md).
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "engine/rt/ray_offset.h"
#include "engine/rt/rt_scene.h"
#include "tests/support/rt_test_geometry.h"

namespace diptych {
namespace {

struct Trial {
  long rays = 0, selfHits = 0, belowPlane = 0, triangles = 0;
};

vec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<float> N(0.f, 1.f);
  for (;;) {
    const vec3 v(N(rng), N(rng), N(rng));
    const float l = glm::length(v);
    if (l > 1e-3f) return v / l;
  }
}

// relativeOffset: the error bound per unit of coordinate magnitude (0: no offset at all).
Trial runTrial(float relativeOffset, int triangles, int pointsPerTriangle, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> U01(0.f, 1.f), logU(-6.f, 6.f);
  RtDevice device;
  Trial trial;
  while (trial.triangles < triangles) {
    const float size = std::pow(10.f, logU(rng)), distance = std::pow(10.f, logU(rng));
    if (size < 1e-4f * distance) continue;  // below float resolution at that distance
    const vec3 centre = distance * randomUnit(rng);
    Mesh mesh;
    for (int k = 0; k < 3; ++k) mesh.positions.push_back(centre + size * randomUnit(rng));
    mesh.indices = {0, 1, 2};
    const glm::dvec3 a(mesh.positions[0]), b(mesh.positions[1]), c(mesh.positions[2]);
    const glm::dvec3 cross = glm::cross(b - a, c - a);
    const double longest = std::max({glm::length(b - a), glm::length(c - a), glm::length(c - b)});
    if (glm::length(cross) < 0.05 * longest * longest) continue;  // slivers: edge-case test
    const glm::dvec3 exactNormal = cross / glm::length(cross);
    ++trial.triangles;
    const WorldGeometry world = flattenScene(testgeo::sceneOf({mesh}));
    RtScene rt(device, world);
    const vec3 n = geometricNormal(world.meshes[0], 0);
    const vec3 magnitude = vertexMagnitude(mesh.positions[0], mesh.positions[1], mesh.positions[2]);
    for (int k = 0; k < pointsPerTriangle; ++k) {
      float u = U01(rng), v = U01(rng);
      if (u + v > 1.f) u = 1.f - u, v = 1.f - v;
      const vec3 p = interpolatePosition(world.meshes[0], 0, u, v);
      vec3 d = randomUnit(rng);
      const vec3 side = glm::dot(d, n) >= 0.f ? n : -n;  // front for reflected, back for transmitted
      const vec3 error = positionErrorBound(p, magnitude) *
                         (relativeOffset / ray_offset::kRelativeOffset);
      const vec3 o = relativeOffset > 0.f ? offsetRayOriginByError(p, side, error) : p;
      const double height = glm::dot(exactNormal, glm::dvec3(o) - a) * glm::dot(glm::dvec3(side), exactNormal);
      trial.belowPlane += height > 0.0 ? 0 : 1;
      ++trial.rays;
      const auto hit = rt.intersect(Ray{o, d}, 0.f, std::numeric_limits<float>::infinity());
      trial.selfHits += hit ? 1 : 0;  // the only geometry is the triangle itself
    }
  }
  return trial;
}

TEST(Reintersection, SecondaryRaysNeverHitTheirOwnTriangleAtAnyScaleOrOffset) {
  const Trial t = runTrial(ray_offset::kRelativeOffset, 2000, 50, 2024);
  std::printf("[numerics] reintersection at 256 eps: %ld rays on %ld triangles, %ld self hits, "
              "%ld origins not above the plane\n",
              t.rays, t.triangles, t.selfHits, t.belowPlane);
  EXPECT_EQ(t.rays, 100000);
  EXPECT_EQ(t.selfHits, 0);
  EXPECT_EQ(t.belowPlane, 0);
}

TEST(Reintersection, TheTrialFailsWithoutOffsetAndShowsTheMargin) {
  // Teeth: rays from the reconstructed point itself re-hit their triangle often.
  const Trial none = runTrial(0.f, 300, 50, 7);
  std::printf("[numerics] reintersection without offset: %ld / %ld self hits\n", none.selfHits,
              none.rays);
  EXPECT_GT(none.selfHits, none.rays / 100);
  // The margin: the smallest constants that still give zero here, for the record.
  for (float k : {1.f, 4.f, 16.f, 64.f}) {
    const Trial t = runTrial(k * FLT_EPSILON, 300, 50, 7);
    std::printf("[numerics] reintersection at %g eps: %ld / %ld self hits, %ld below plane\n",
                double(k), t.selfHits, t.rays, t.belowPlane);
  }
}

}  // namespace
}  // namespace diptych
