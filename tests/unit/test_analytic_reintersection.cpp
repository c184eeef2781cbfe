// Reintersection robustness of the analytic quadrics, after pbrt-v4's shapes test
// (src/pbrt/shapes_test.cpp, "reintersect" tests): random shapes under random transforms whose
// scale and translation are log-uniform over 1e-6 .. 1e6 (non-uniform, rotated, half of them
// mirrored); a ray from a random point outside toward a random point on the surface; at the hit
// Embree reports, a secondary ray leaving to the side the ray came from (spawnRay: the robust
// offset of engine/rt/ray_offset.h, unchanged here) must not hit the shape again. Every shape is
// convex or part of a convex solid's boundary, and the ray arrives from outside, so such a hit
// can only be a self-intersection. Misses of the first ray (float cannot place a 1e-6 shape
// 1e6 from the origin, or aim at it) are counted and reported, not failures.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "engine/rt/rt_scene.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/primitives.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

struct Counts {
  int trials = 0, misses = 0, selfHits = 0, nonFinite = 0;
};

class Sampler {
 public:
  explicit Sampler(std::uint32_t seed) : rng_(seed) {}
  double uniform() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
  double logUniform(double lo, double hi) {
    return std::exp(std::log(lo) + uniform() * (std::log(hi) - std::log(lo)));
  }
  dvec3 unitVector() {
    const double z = 2.0 * uniform() - 1.0, phi = 2.0 * 3.141592653589793 * uniform();
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
  }
  // A direction in the hemisphere around n (not too close to grazing).
  dvec3 hemisphere(const dvec3& n) {
    for (;;) {
      const dvec3 w = unitVector();
      const double c = glm::dot(w, n);
      if (std::abs(c) > 1e-3) return c > 0.0 ? w : -w;
    }
  }

 private:
  std::mt19937 rng_;
};

mat4 randomTransform(Sampler& s) {
  const double scale = s.logUniform(1e-6, 1e6);
  dvec3 axes(scale * (0.5 + 1.5 * s.uniform()), scale * (0.5 + 1.5 * s.uniform()),
             scale * (0.5 + 1.5 * s.uniform()));
  if (s.uniform() < 0.5) axes.x = -axes.x;  // mirrored
  dvec3 t;
  for (int i = 0; i < 3; ++i) t[i] = (s.uniform() < 0.5 ? -1 : 1) * s.logUniform(1e-6, 1e6);
  const glm::dquat q = glm::angleAxis(6.283185307179586 * s.uniform(), s.unitVector());
  const glm::dmat4 m =
      glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(q) * glm::scale(glm::dmat4(1.0), axes);
  return mat4(m);
}

// A random uv on part (planar parts: uniform over the disc).
vec2 randomUv(Sampler& s, const AnalyticShape& shape, int part) {
  if (shape.type == ShapeType::Disc || part > 0) {
    const double r = 0.5 * std::sqrt(s.uniform()), phi = 6.283185307179586 * s.uniform();
    return vec2(float(0.5 + r * std::cos(phi)), float(0.5 + r * std::sin(phi)));
  }
  return vec2(float(s.uniform()), float(0.02 + 0.96 * s.uniform()));
}

Counts reintersect(const AnalyticShape& shape, int transforms, int raysPerTransform,
                   std::uint32_t seed) {
  Sampler s(seed);
  RtDevice device;
  Counts c;
  for (int k = 0; k < transforms; ++k) {
    Scene scene;
    Mesh mesh = makeUvSphere(1.f, 3, 2);  // unused by the tracer; the exact shape is traced
    mesh.analytic = shape;
    scene.meshes.push_back(mesh);
    scene.instances.push_back({"shape", 0, randomTransform(s)});
    const WorldGeometry world = flattenScene(scene);
    const AnalyticInstance& a = *world.meshes[0].analytic;
    RtScene rt(device, world, scene);
    const double extent = glm::length(glm::dvec3(a.bounds.hi) - glm::dvec3(a.bounds.lo));
    for (int r = 0; r < raysPerTransform; ++r) {
      ++c.trials;
      const int part = int(s.uniform() * partCount(shape)) % partCount(shape);
      const vec2 uv = randomUv(s, shape, part);
      const dvec3 p = dvec3(a.toWorld * glm::dvec4(shapePoint(shape, part, uv), 1.0));
      const dvec3 n = dvec3(analyticNormal(a, part, uv));
      // Discs are two-sided: either side; others: the outward side.
      const dvec3 side = shape.type == ShapeType::Disc && s.uniform() < 0.5 ? -n : n;
      const dvec3 origin = p + s.logUniform(1e-2, 1e2) * extent * s.hemisphere(side);
      const vec3 dir = vec3(glm::normalize(p - origin));
      const auto hit =
          rt.intersect({vec3(origin), dir}, 0.f, std::numeric_limits<float>::infinity());
      if (!hit) {
        ++c.misses;
        continue;
      }
      const SurfacePoint sp = makeSurfacePoint(
          scene, world, {hit->instance, hit->primitive, hit->u, hit->v, hit->analytic}, dir);
      if (!allFinite(sp.position) || !allFinite(sp.geometricNormal)) {
        ++c.nonFinite;
        continue;
      }
      // Leave toward the side the ray came from (geometricNormal faces it).
      const vec3 w = vec3(s.hemisphere(dvec3(sp.geometricNormal)));
      const Ray out = spawnRay(sp, w);
      if (rt.intersect(out, 0.f, std::numeric_limits<float>::infinity())) ++c.selfHits;
    }
  }
  return c;
}

void check(const char* name, const AnalyticShape& shape, std::uint32_t seed) {
  const Counts c = reintersect(shape, 200, 20, seed);
  std::printf(
      "[reintersection] %-16s trials %d, first-ray misses %d, self-hits %d, non-finite %d\n", name,
      c.trials, c.misses, c.selfHits, c.nonFinite);
  ::testing::Test::RecordProperty(std::string(name) + ".self_hits", c.selfHits);
  ::testing::Test::RecordProperty(std::string(name) + ".misses", c.misses);
  EXPECT_EQ(c.selfHits, 0) << name;
  EXPECT_EQ(c.nonFinite, 0) << name;
  // Most first rays must hit, or the test tests nothing.
  EXPECT_GT(c.trials - c.misses, c.trials / 2) << name;
}

TEST(AnalyticReintersection, SphereNeverReHitsItself) {
  check("sphere", {ShapeType::Sphere, 1.f}, 1);
}
TEST(AnalyticReintersection, DiscNeverReHitsItself) {
  check("disc", {ShapeType::Disc, 1.f}, 2);
}
TEST(AnalyticReintersection, CappedCylinderNeverReHitsItself) {
  check("capped cylinder", {ShapeType::Cylinder, 0.5f, 2.f, true}, 3);
}
TEST(AnalyticReintersection, OpenCylinderNeverReHitsItself) {
  check("open cylinder", {ShapeType::Cylinder, 1.f, 0.5f, false}, 4);
}
TEST(AnalyticReintersection, ConeNeverReHitsItself) {
  check("cone", {ShapeType::Cone, 1.f, 1.5f, true}, 5);
}
}  // namespace DIPTYCH_UNITY_ID
