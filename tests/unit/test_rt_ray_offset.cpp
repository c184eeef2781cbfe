// Robust ray origins (pbrt-v4 error bounds, engine/rt/ray_offset.h) and shadow-ray margins,
// checked on random triangles of scale 1e-4 .. 1e4, near and far from the origin.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "engine/rt/ray_offset.h"
#include "engine/rt/rt_scene.h"
#include "tests/support/rt_test_geometry.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

struct RandomTriangle {
  vec3 p[3];
  glm::dvec3 normal;  // unit, double, from the float vertices
};

// A triangle of size ~scale with its centre at distance scale * 10^[-1, 3] from the origin.
RandomTriangle randomTriangle(std::mt19937& rng, float scale) {
  std::normal_distribution<float> N(0.f, 1.f);
  std::uniform_real_distribution<float> U(-1.f, 3.f);
  const vec3 centre = glm::normalize(vec3(N(rng), N(rng), N(rng))) * scale * std::pow(10.f, U(rng));
  for (;;) {
    RandomTriangle t;
    for (vec3& v : t.p) v = centre + scale * vec3(N(rng), N(rng), N(rng));
    const glm::dvec3 a(t.p[0]), b(t.p[1]), c(t.p[2]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double longest = std::max({glm::length(b - a), glm::length(c - a), glm::length(c - b)});
    // Skip slivers: they have no well-defined plane at float precision.
    if (glm::length(n) < 0.05 * longest * longest) continue;
    t.normal = n / glm::length(n);
    return t;
  }
}

// Signed distance of x from the triangle's plane, in double.
double planeDistance(const RandomTriangle& t, vec3 x) {
  return glm::dot(t.normal, glm::dvec3(x) - glm::dvec3(t.p[0]));
}

struct OffsetStats {
  int belowPlane = 0, selfHits = 0, samples = 0;
};

// 1000 triangles x 100 points: origin side and self-hit freedom of shadow rays toward lights
// above the triangle (including near-grazing ones).
OffsetStats runOffsetTrial(bool useVertexMagnitude, float minCentreFactor, bool offset = true) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> U01(0.f, 1.f);
  std::uniform_real_distribution<float> logScale(-4.f, 4.f);
  RtDevice device;
  OffsetStats stats;
  for (int tri = 0; tri < 1000; ++tri) {
    const float scale = std::pow(10.f, logScale(rng));
    RandomTriangle t = randomTriangle(rng, scale);
    if (glm::length(glm::dvec3(t.p[0])) < minCentreFactor * scale) {
      --tri;
      continue;
    }
    Mesh mesh;
    mesh.positions = {t.p[0], t.p[1], t.p[2]};
    mesh.indices = {0, 1, 2};
    const WorldGeometry world = flattenScene(testgeo::sceneOf({mesh}));
    RtScene rt(device, world);
    const vec3 n = geometricNormal(world.meshes[0], 0);
    const vec3 magnitude = useVertexMagnitude ? vertexMagnitude(t.p[0], t.p[1], t.p[2]) : vec3(0.f);
    // Tangent frame for placing lights.
    const glm::dvec3 e1 = glm::normalize(glm::dvec3(t.p[1]) - glm::dvec3(t.p[0]));
    const glm::dvec3 e2 = glm::cross(t.normal, e1);
    for (int k = 0; k < 100; ++k) {
      float u = U01(rng), v = U01(rng);
      if (u + v > 1.f) u = 1.f - u, v = 1.f - v;
      const vec3 p = interpolatePosition(world.meshes[0], 0, u, v);
      const vec3 o = offset ? offsetRayOrigin(p, n, magnitude) : p;
      ++stats.samples;
      if (!(planeDistance(t, o) > 0.0)) ++stats.belowPlane;
      // Light above the plane: height 0.1 .. 10 scale, lateral 0.1 .. 30 scale (grazing down to
      // a few milliradians).
      const double h = scale * std::pow(10.0, -1.0 + 2.0 * U01(rng));
      const double lateral = scale * std::pow(10.0, -1.0 + 2.5 * U01(rng));
      const double phi = 6.283185307 * U01(rng);
      const glm::dvec3 light =
          glm::dvec3(p) + h * t.normal + lateral * (std::cos(phi) * e1 + std::sin(phi) * e2);
      const ShadowSegment s = shadowSegmentTo(o, vec3(light));
      if (s.tfar > 0.f && rt.occluded(o, s.direction, 0.f, s.tfar)) ++stats.selfHits;
    }
  }
  return stats;
}

TEST(RayOffset, StepIsRelativeToTheCoordinatesWithNoAbsoluteFloor) {
  // Off an axis plane through the origin the step along n is kCrossOffset * max|coordinate|
  // (plus one float of rounding away), at every magnitude: no absolute fallback near the origin
  // (the floor of issue 13).
  const vec3 n(0.f, 1.f, 0.f);
  for (float x : {1e-30f, 1e-6f, 1e-2f, 1.f, 1e6f}) {
    const vec3 o = offsetRayOrigin(vec3(x, 0.f, -0.5f * x), n);
    EXPECT_GE(o.y, ray_offset::kCrossOffset * x) << x;
    EXPECT_LE(o.y, 1.01f * ray_offset::kCrossOffset * x) << x;
    EXPECT_EQ(o.x, x);
  }
  // Exactly scale-equivariant under powers of two: the origins of a scene scaled by 2^k are the
  // origins of the scene, scaled.
  const vec3 p(0.3f, 1.7f, -2.2f), tilted = glm::normalize(vec3(0.2f, 1.f, -0.4f));
  const vec3 m(4.f, 2.f, 3.f);
  for (int k : {-60, -20, 0, 20, 60}) {
    const float s = std::ldexp(1.f, k);
    EXPECT_EQ(offsetRayOrigin(p * s, tilted, m * s), offsetRayOrigin(p, tilted, m) * s) << k;
  }
  // The vertex magnitude, not p, sets the step near an axis plane.
  EXPECT_EQ(offsetRayOrigin(vec3(0.f), n, vec3(1000.f, 0.f, 0.f)).y,
            std::nextafter(ray_offset::kCrossOffset * 1000.f, 1.f));
  // At the origin itself (degenerate: nothing to scale by) the point still moves.
  EXPECT_GT(offsetRayOrigin(vec3(0.f), n).y, 0.f);
}

TEST(RayOffset, OriginsLeaveThePlaneAndShadowRaysNeverHitTheirOwnTriangle) {
  const OffsetStats s = runOffsetTrial(/*useVertexMagnitude=*/true, /*minCentreFactor=*/0.f);
  EXPECT_EQ(s.samples, 100000);
  EXPECT_EQ(s.belowPlane, 0);
  EXPECT_EQ(s.selfHits, 0);
}

TEST(RayOffset, WithoutOffsetTheSameTrialFails) {
  // The trial has teeth: origins left on the reconstructed point fall below the plane and
  // self-intersect in a large fraction of samples.
  const OffsetStats s = runOffsetTrial(true, 0.f, /*offset=*/false);
  EXPECT_GT(s.belowPlane, s.samples / 10);
  EXPECT_GT(s.selfHits, s.samples / 100);
}

TEST(RayOffset, OffsetWithoutVertexMagnitudeIsRobustAwayFromTheOrigin) {
  // Without the vertex magnitude, the offset (relative to |p| alone) is robust where |p| is the
  // scale of the vertices, i.e. for triangles whose distance from the origin exceeds their size.
  const OffsetStats s = runOffsetTrial(/*useVertexMagnitude=*/false, /*minCentreFactor=*/10.f);
  EXPECT_EQ(s.belowPlane, 0);
  EXPECT_EQ(s.selfHits, 0);
}

TEST(ShadowSegment, StopsShortByARelativeMargin) {
  for (float scale : {1e-4f, 1.f, 1e4f}) {
    const vec3 o(scale, 2.f * scale, -scale), target(3.f * scale, -scale, 5.f * scale);
    const ShadowSegment s = shadowSegmentTo(o, target);
    const float d = glm::length(target - o);
    EXPECT_LT(s.tfar, d);
    EXPECT_GT(s.tfar, d * (1.f - 1e-5f));
    EXPECT_NEAR(glm::length(s.direction), 1.f, 1e-6f);
  }
  EXPECT_LT(shadowSegmentTo(vec3(1.f), vec3(1.f)).tfar, 0.f);  // no segment
}

TEST(ShadowSegment, LightOnAnEmitterSurfaceIsNotShadowedByIt) {
  // A light exactly on a triangle (a lamp's quad), far from the origin: the segment from a
  // receiver below must not reach the triangle the light sits on.
  Mesh lamp;
  lamp.positions = {{1000.f, 50.f, 1000.f}, {1010.f, 50.f, 1000.f}, {1000.f, 50.f, 1010.f}};
  lamp.indices = {0, 1, 2};
  const WorldGeometry world = flattenScene(testgeo::sceneOf({lamp}));
  RtDevice device;
  RtScene rt(device, world);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> U(0.f, 1.f);
  int hits = 0;
  for (int i = 0; i < 10000; ++i) {
    float u = U(rng), v = U(rng);
    if (u + v > 1.f) u = 1.f - u, v = 1.f - v;
    const vec3 light = interpolatePosition(world.meshes[0], 0, u, v);
    const vec3 receiver(1000.f + 20.f * U(rng), 0.f, 1000.f + 20.f * U(rng));
    const ShadowSegment s = shadowSegmentTo(receiver, light);
    hits += rt.occluded(receiver, s.direction, 0.f, s.tfar);
  }
  EXPECT_EQ(hits, 0);
}

TEST(RayOffset, LargeTriangleThroughTheOriginNeedsTheVertexMagnitude) {
  // A 1e4-sized triangle, tilted, whose centroid is the origin: near the centroid |p| is tiny,
  // but p carries rounding errors of ULPs of 1e4. An offset relative to |p| alone is far too small
  // there and leaves origins below the plane; one relative to the vertex magnitude does not.
  RandomTriangle t;
  t.p[0] = vec3(-1e4f, -5e3f, 7.5e3f);
  t.p[1] = vec3(1e4f, -5e3f, -7.5e3f);
  t.p[2] = vec3(0.f, 1e4f, 0.f);
  const glm::dvec3 a(t.p[0]), b(t.p[1]), c(t.p[2]);
  t.normal = glm::normalize(glm::cross(b - a, c - a));
  Mesh mesh;
  mesh.positions = {t.p[0], t.p[1], t.p[2]};
  mesh.indices = {0, 1, 2};
  const WorldGeometry world = flattenScene(testgeo::sceneOf({mesh}));
  const vec3 n = geometricNormal(world.meshes[0], 0);
  const vec3 magnitude = vertexMagnitude(t.p[0], t.p[1], t.p[2]);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> J(-1e-6f, 1e-6f);
  int plainBelow = 0, extendedBelow = 0;
  for (int i = 0; i < 10000; ++i) {
    const vec3 p = interpolatePosition(world.meshes[0], 0, 1.f / 3.f + J(rng), 1.f / 3.f + J(rng));
    plainBelow += !(planeDistance(t, offsetRayOrigin(p, n)) > 0.0);
    extendedBelow += !(planeDistance(t, offsetRayOrigin(p, n, magnitude)) > 0.0);
  }
  EXPECT_GT(plainBelow, 0);
  EXPECT_EQ(extendedBelow, 0);
}

// The inline nextFloatUp/Down replace std::nextafter in offsetRayOriginByError: they must give
// the same float for every class of input (zeros, denormals, the largest finite, infinities,
// NaN) and for random bit patterns.
TEST(RayOffset, NextFloatUpAndDownAreStdNextafter) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const auto same = [](float a, float b) {
    return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b) ||
           (std::isnan(a) && std::isnan(b));
  };
  std::vector<float> inputs = {0.f,
                               -0.f,
                               1.f,
                               -1.f,
                               std::numeric_limits<float>::denorm_min(),
                               -std::numeric_limits<float>::denorm_min(),
                               std::numeric_limits<float>::min(),
                               -std::numeric_limits<float>::min(),
                               std::numeric_limits<float>::max(),
                               -std::numeric_limits<float>::max(),
                               kInf,
                               -kInf,
                               std::numeric_limits<float>::quiet_NaN()};
  std::mt19937 rng(14);
  for (int i = 0; i < 100000; ++i) inputs.push_back(std::bit_cast<float>(std::uint32_t(rng())));
  for (const float x : inputs) {
    EXPECT_TRUE(same(nextFloatUp(x), std::nextafter(x, kInf))) << x;
    EXPECT_TRUE(same(nextFloatDown(x), std::nextafter(x, -kInf))) << x;
  }
}
}  // namespace DIPTYCH_UNITY_ID
