// pbrt-style reintersection test (pbrt-v4's "Triangle, Reintersect" test, here against Embree):
// random triangles of log-uniform size 1e-6 .. 1e6 at log-uniform distance 1e-6 .. 1e6 from the
// origin (kept where the float vertices still resolve the triangle: size >= 1e-4 x distance),
// random points on them, and secondary rays leaving in random directions of either hemisphere
// (reflected: offset to the front, transmitted: to the back; half of them grazing, 1e-4 .. 1
// rad off the plane) from offsetRayOrigin. A ray that
// leaves a flat triangle can never meet it again, so every hit of its own triangle is a
// self-intersection ("miss" of the offset). Bound: zero with the engine's constants. The same
// trial with smaller constants is printed to show the margin (docs/numerics.md).
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
namespace DIPTYCH_UNITY_ID {

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

// axis, cross: the two constants of positionErrorBound (both 0: no offset at all).
Trial runTrial(float axisK, float crossK, int triangles, int pointsPerTriangle,
               std::uint32_t seed) {
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
      // Half the rays uniform, half grazing: 10^[-4, 0] rad off the plane, either side.
      vec3 d = randomUnit(rng);
      if (k % 2) {
        const vec3 tangent = glm::normalize(d - glm::dot(d, n) * n);
        const float lift = std::pow(10.f, -4.f * U01(rng)) * (U01(rng) < 0.5f ? -1.f : 1.f);
        d = glm::normalize(tangent + lift * n);
      }
      const vec3 side =
          glm::dot(d, n) >= 0.f ? n : -n;  // front for reflected, back for transmitted
      const vec3 error = positionErrorBound(p, magnitude, axisK, crossK);
      const vec3 o = axisK + crossK > 0.f ? offsetRayOriginByError(p, side, error) : p;
      const double height =
          glm::dot(exactNormal, glm::dvec3(o) - a) * glm::dot(glm::dvec3(side), exactNormal);
      trial.belowPlane += height > 0.0 ? 0 : 1;
      ++trial.rays;
      const auto hit = rt.intersect(Ray{o, d}, 0.f, std::numeric_limits<float>::infinity());
      trial.selfHits += hit ? 1 : 0;  // the only geometry is the triangle itself
    }
  }
  return trial;
}

TEST(Reintersection, SecondaryRaysNeverHitTheirOwnTriangleAtAnyScaleOrOffset) {
  const Trial t = runTrial(ray_offset::kAxisOffset, ray_offset::kCrossOffset, 2000, 50, 2024);
  std::printf(
      "[numerics] reintersection, engine constants: %ld rays on %ld triangles, %ld self hits, "
      "%ld origins not above the plane\n",
      t.rays, t.triangles, t.selfHits, t.belowPlane);
  EXPECT_EQ(t.rays, 100000);
  EXPECT_EQ(t.selfHits, 0);
  EXPECT_EQ(t.belowPlane, 0);
}

TEST(Reintersection, TheTrialFailsWithoutOffsetAndShowsTheMargin) {
  // Teeth: rays from the reconstructed point itself re-hit their triangle often.
  const Trial none = runTrial(0.f, 0.f, 300, 50, 7);
  std::printf("[numerics] reintersection without offset: %ld / %ld self hits\n", none.selfHits,
              none.rays);
  EXPECT_GT(none.selfHits, none.rays / 100);
  // The margin, for the record: each term alone, and the cross-axis term scaled down.
  const struct {
    float axis, cross;
  } variants[] = {{ray_offset::kAxisOffset, 0.f},
                  {0.f, ray_offset::kCrossOffset},
                  {0.f, FLT_EPSILON},
                  {0.f, 0.25f * FLT_EPSILON}};
  long tooSmall = 0;
  for (const auto& v : variants) {
    const Trial t = runTrial(v.axis, v.cross, 2000, 50, 2024);
    if (v.axis == 0.f && v.cross < FLT_EPSILON) tooSmall = t.selfHits;
    std::printf(
        "[numerics] reintersection, axis %g eps + cross %g eps: %ld / %ld self hits, %ld "
        "below plane\n",
        double(v.axis / FLT_EPSILON), double(v.cross / FLT_EPSILON), t.selfHits, t.rays,
        t.belowPlane);
  }
  EXPECT_GT(tooSmall, 0) << "a cross term of 0.25 eps alone is expected to be too small";
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
