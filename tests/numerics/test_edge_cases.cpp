// Numerical edge cases with their expected answers (docs/numerics.md):
//  - grazing incidence: a ray meeting a plane at 1e-1 .. 1e-4 rad reflects off it without
//    re-hitting it, and a light 1e-2 .. 1e-4 rad above the horizon is visible, at every scale;
//  - total internal reflection at the critical angle +- 1e-6 rad (glass to air, ior 1.5):
//    just above it TIR with the mirror direction, just below it a finite unit transmitted ray
//    nearly along the surface, both agreeing with a double-precision evaluation;
//  - degenerate triangles (repeated or collinear vertices) cover no pixel and cast no shadow:
//    the image with them is the image without them, and finite;
//  - sliver triangles (aspect 1e4): rays leaving at more than 0.01 rad from the plane never
//    re-hit their triangle;
//  - coplanar overlapping surfaces (two differently triangulated quads in one tilted plane):
//    every primary ray hits one of them, and neither blocks the other's shadow or transmitted
//    rays: coplanar twins act as one surface for secondary rays.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "engine/metrics/metrics.h"
#include "engine/rt/ray_offset.h"
#include "engine/rt/rt_scene.h"
#include "engine/rt/shadow_rays.h"
#include "engine/rt/surface_point.h"
#include "engine/shading/shading.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/rt_test_geometry.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(EdgeCases, GrazingReflectionsAndShadowRaysLeaveThePlane) {
  RtDevice device;
  for (float scale : {1e-6f, 1.f, 1e6f}) {
    Scene scene = testgeo::sceneOf({testgeo::groundPlane(1000.f * scale)});
    const WorldGeometry world = flattenScene(scene);
    RtScene rt(device, world);
    int selfHits = 0, shadowed = 0, hits = 0;
    for (double angle : {1e-1, 1e-2, 1e-3, 1e-4}) {
      for (float x : {-3.f, 0.5f, 7.f}) {
        // A ray arriving at angle `angle` below the horizon at (x, 0, 0) * scale.
        const vec3 target(x * scale, 0.f, 0.3f * scale);
        const vec3 d = glm::normalize(vec3(float(std::cos(angle)), float(-std::sin(angle)), 0.f));
        const Ray primary{target - 10.f * scale * d, d};
        const auto hit = rt.intersect(primary, 0.f, kInf);
        if (!hit) continue;
        ++hits;
        const SurfacePoint p =
            makeSurfacePoint(scene, world, {hit->instance, hit->primitive, hit->u, hit->v}, d);
        const vec3 r = glm::normalize(shading::reflectAbout(-d, p.shadingNormal));
        selfHits += rt.intersect(spawnRay(p, r), 0.f, kInf) ? 1 : 0;
        // A light just above the horizon, 100 units away.
        Light light;
        light.position =
            p.position + 100.f * scale * vec3(float(std::cos(angle)), float(std::sin(angle)), 0.f);
        const OcclusionRay s =
            makeShadowRay(light, {p.position, p.faceNormal, p.positionMagnitude});
        shadowed += rt.occluded(s.origin, s.direction, s.tnear, s.tfar) ? 1 : 0;
      }
    }
    EXPECT_EQ(hits, 12) << scale;
    EXPECT_EQ(selfHits, 0) << scale;
    EXPECT_EQ(shadowed, 0) << scale;
  }
}

TEST(EdgeCases, TotalInternalReflectionAtTheCriticalAngle) {
  const double eta = 1.5;  // leaving glass: n_i / n_t
  const double critical = std::asin(1.0 / eta);
  const vec3 n(0.f, 1.f, 0.f);
  for (double delta : {1e-6, -1e-6}) {
    const double theta = critical + delta;
    // i points from the surface toward where the light comes from (inside the glass).
    const vec3 i(float(std::sin(theta)), float(std::cos(theta)), 0.f);
    const shading::Refraction r = shading::refractLecture(i, n, float(eta));
    const double sin2T = eta * eta * (1.0 - double(i.y) * double(i.y));  // double reference
    EXPECT_EQ(r.totalInternalReflection, sin2T > 1.0) << delta;
    EXPECT_EQ(r.totalInternalReflection, delta > 0) << delta;
    EXPECT_NEAR(glm::length(r.t), 1.f, 1e-6f);
    EXPECT_TRUE(std::isfinite(r.t.x) && std::isfinite(r.t.y) && std::isfinite(r.t.z));
    if (r.totalInternalReflection) {
      EXPECT_NEAR(r.t.x, -i.x, 1e-6f);  // the mirror direction, same side as i
      EXPECT_NEAR(r.t.y, i.y, 1e-6f);
    } else {
      // Through the surface, nearly tangent: cos(theta_t) = sqrt(1 - sin2T) ~ 2e-3.
      EXPECT_LT(r.t.y, 0.f);
      EXPECT_NEAR(double(-r.t.y), std::sqrt(1.0 - sin2T), 2e-4);
    }
  }
}

Image renderWhitted(const Scene& scene) {
  const Recipe recipe = loadRecipe(std::string(DIPTYCH_SAMPLES_DIR) + "/graphs/whitted.json");
  auto f = testing::renderHybridFrame(scene, 160, 120, {}, recipe);
  return f->output(recipe.outputs.at(0)).toImage();
}

TEST(EdgeCases, DegenerateTrianglesAreInvisibleAndHarmless) {
  Scene scene = loadScene(std::string(DIPTYCH_SAMPLES_DIR) + "/scenes/shadow-sphere.json");
  const Image without = renderWhitted(scene);
  Mesh degenerate;
  degenerate.name = "degenerate";
  // Between the light and the floor, in view: a repeated vertex, three collinear vertices, and
  // all three vertices equal.
  degenerate.positions = {{-1.f, 0.5f, 1.f}, {1.f, 0.5f, 1.f}, {0.f, 0.5f, 2.f},
                          {-2.f, 0.1f, 2.f}, {0.f, 0.1f, 2.f}, {2.f, 0.1f, 2.f}};
  degenerate.indices = {0, 0, 2, 3, 4, 5, 1, 1, 1};
  scene.meshes.push_back(degenerate);
  scene.instances.push_back({"degenerate", int(scene.meshes.size()) - 1, mat4(1.f)});
  const Image with = renderWhitted(scene);
  long nonFinite = 0;
  for (float v : with.pixels) nonFinite += std::isfinite(v) ? 0 : 1;
  EXPECT_EQ(nonFinite, 0);
  MetricOptions o;
  o.metrics = {"mse"};
  EXPECT_EQ(computeMetrics(with, without, o).at("mse"), 0.0);
  const WorldGeometry world = flattenScene(scene);
  const vec3 n = geometricNormal(world.meshes.back(), 0);
  EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
}

TEST(EdgeCases, SliverTrianglesDoNotReintersect) {
  RtDevice device;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> U(0.f, 1.f);
  std::normal_distribution<float> N(0.f, 1.f);
  long rays = 0, selfHits = 0, skipped = 0;
  for (float scale : {1e-5f, 1.f, 1e5f}) {
    Mesh m;
    // Long edge 1, width 1e-4, tilted, away from the origin.
    const vec3 base = scale * vec3(3.f, -2.f, 5.f);
    const vec3 a = glm::normalize(vec3(1.f, 0.3f, -0.2f)),
               b = glm::normalize(vec3(0.1f, 1.f, 0.4f));
    m.positions = {base, base + scale * a, base + scale * (0.5f * a + 1e-4f * b)};
    m.indices = {0, 1, 2};
    const WorldGeometry world = flattenScene(testgeo::sceneOf({m}));
    RtScene rt(device, world);
    const glm::dvec3 exact = glm::normalize(glm::cross(
        glm::dvec3(m.positions[1] - m.positions[0]), glm::dvec3(m.positions[2] - m.positions[0])));
    const vec3 n = geometricNormal(world.meshes[0], 0);
    const vec3 magnitude = vertexMagnitude(m.positions[0], m.positions[1], m.positions[2]);
    for (int k = 0; k < 5000; ++k) {
      float u = U(rng), v = U(rng);
      if (u + v > 1.f) u = 1.f - u, v = 1.f - v;
      const vec3 p = interpolatePosition(world.meshes[0], 0, u, v);
      const vec3 d = glm::normalize(vec3(N(rng), N(rng), N(rng)));
      if (std::abs(glm::dot(glm::dvec3(d), exact)) < 0.01) {
        ++skipped;  // within the sliver normal's own error of the plane: no defined side
        continue;
      }
      const vec3 o = offsetRayOrigin(p, glm::dot(d, n) >= 0.f ? n : -n, magnitude);
      ++rays;
      selfHits += rt.intersect(Ray{o, d}, 0.f, kInf) ? 1 : 0;
    }
  }
  std::printf("[numerics] slivers: %ld rays, %ld self hits (%ld near-tangent rays skipped)\n", rays,
              selfHits, skipped);
  EXPECT_EQ(selfHits, 0);
}

TEST(EdgeCases, CoplanarOverlappingSurfacesActAsOneForSecondaryRays) {
  // Two quads over the same region of one tilted plane, triangulated along opposite diagonals.
  const vec3 origin(3.f, 1.f, 2.f);
  const vec3 e1 = glm::normalize(vec3(1.f, 0.2f, 0.1f)),
             e2 = glm::normalize(vec3(-0.1f, 0.3f, 1.f));
  const auto corner = [&](float s, float t) { return origin + 4.f * s * e1 + 4.f * t * e2; };
  Mesh a, b;
  a.positions = b.positions = {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
  a.indices = {0, 1, 2, 0, 2, 3};
  b.indices = {0, 1, 3, 1, 2, 3};
  const Scene scene = testgeo::sceneOf({a, b});
  const WorldGeometry world = flattenScene(scene);
  RtDevice device;
  RtScene rt(device, world);
  const vec3 n = geometricNormal(world.meshes[0], 0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> U(0.05f, 0.95f);
  int missed = 0, blocked = 0, transmittedBlocked = 0;
  for (int k = 0; k < 4000; ++k) {
    const vec3 target = corner(U(rng), U(rng));
    const Ray primary{target + 10.f * n, -n};
    const auto hit = rt.intersect(primary, 0.f, kInf);
    if (!hit) {
      ++missed;
      continue;
    }
    const SurfacePoint p =
        makeSurfacePoint(scene, world, {hit->instance, hit->primitive, hit->u, hit->v}, -n);
    Light light;
    light.position = p.position + 5.f * glm::normalize(n + 0.3f * e1);
    const OcclusionRay s = makeShadowRay(light, {p.position, p.faceNormal, p.positionMagnitude});
    blocked += rt.occluded(s.origin, s.direction, s.tnear, s.tfar) ? 1 : 0;
    const Ray through = spawnRay(p, glm::normalize(-n + 0.2f * e2));
    transmittedBlocked += rt.intersect(through, 0.f, kInf) ? 1 : 0;
  }
  EXPECT_EQ(missed, 0);
  EXPECT_EQ(blocked, 0);
  EXPECT_EQ(transmittedBlocked, 0);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
