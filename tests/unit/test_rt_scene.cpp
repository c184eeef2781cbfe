// Embree scene: exact hits, instance ids, mirrored instances, occlusion, batches, errors.
#include <gtest/gtest.h>

#include <random>

#include "engine/core/error.h"
#include "engine/rt/rt_scene.h"
#include "tests/support/rt_test_geometry.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

Mesh triangleMesh(vec3 a, vec3 b, vec3 c) {
  Mesh m;
  m.name = "triangle";
  m.positions = {a, b, c};
  m.indices = {0, 1, 2};
  return m;
}

glm::dvec3 toD(vec3 v) {
  return glm::dvec3(v);
}

TEST(RtScene, HitOnKnownTriangleMatchesAnalyticTAndInterpolatePosition) {
  const vec3 p0(1.f, 2.f, 3.f), p1(4.f, 2.5f, 3.2f), p2(1.5f, 5.f, 2.8f);
  const WorldGeometry world = flattenScene(testgeo::sceneOf({triangleMesh(p0, p1, p2)}));
  RtDevice device;
  RtScene rt(device, world);

  const double u = 0.2, v = 0.3;
  const glm::dvec3 q = (1 - u - v) * toD(p0) + u * toD(p1) + v * toD(p2);
  const glm::dvec3 o(-2.0, -1.0, 9.0);
  const glm::dvec3 d = glm::normalize(q - o);
  const auto hit = rt.intersect(Ray{vec3(o), vec3(d)}, 0.f, 1e30f);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->instance, 0);
  EXPECT_EQ(hit->primitive, 0u);
  // Analytic t: plane through p0 with normal N, in double.
  const glm::dvec3 N = glm::cross(toD(p1) - toD(p0), toD(p2) - toD(p0));
  const double t = glm::dot(toD(p0) - o, N) / glm::dot(d, N);
  EXPECT_NEAR(hit->t, t, 1e-6 * t);
  EXPECT_NEAR(hit->u, u, 1e-5);
  EXPECT_NEAR(hit->v, v, 1e-5);
  // The reconstructed position is the point on the ray at hit t (relative 1e-6).
  const glm::dvec3 p = toD(interpolatePosition(world.meshes[0], hit->primitive, hit->u, hit->v));
  const glm::dvec3 onRay = o + double(hit->t) * d;
  EXPECT_LT(glm::length(p - onRay), 1e-6 * glm::length(q));
  // Embree's Ng is parallel to the CCW face normal (sign documented in the header).
  const vec3 ng = glm::normalize(hit->Ng);
  EXPECT_NEAR(std::abs(glm::dot(ng, geometricNormal(world.meshes[0], 0))), 1.f, 1e-6f);
  EXPECT_GT(glm::dot(ng, geometricNormal(world.meshes[0], 0)), 0.f);
}

TEST(RtScene, GeometryIdIsInstanceIndexIncludingEmptyMeshesAndMirrors) {
  Scene scene = testgeo::sceneOf({triangleMesh({-1, -1, 0}, {1, -1, 0}, {0, 1, 0}), Mesh{}});
  // Instance 1 uses the empty mesh; 2 and 3 reuse the triangle shifted and mirrored in x.
  scene.instances.push_back(
      Instance{"shifted", 0, glm::translate(mat4(1.f), vec3(10.f, 0.f, 0.f))});
  scene.instances.push_back(Instance{
      "mirrored", 0, glm::scale(glm::translate(mat4(1.f), vec3(20.f, 0.f, 0.f)), vec3(-1, 1, 1))});
  const WorldGeometry world = flattenScene(scene);
  ASSERT_TRUE(world.meshes[3].mirrored);
  RtDevice device;
  RtScene rt(device, world);
  for (int instance : {0, 2, 3}) {
    const float x = instance == 0 ? 0.f : (instance == 2 ? 10.f : 20.f);
    for (float z : {5.f, -5.f}) {  // from the front and from the back: triangles are two-sided
      const auto hit =
          rt.intersect(Ray{vec3(x + 0.1f, -0.2f, z), vec3(0, 0, z > 0 ? -1 : 1)}, 0.f, 100.f);
      ASSERT_TRUE(hit) << "instance " << instance << " z " << z;
      EXPECT_EQ(hit->instance, instance);
      EXPECT_NEAR(hit->t, 5.f, 1e-5f);
      const vec3 p = interpolatePosition(world.meshes[instance], hit->primitive, hit->u, hit->v);
      EXPECT_NEAR(p.x, x + 0.1f, 1e-5f);
      EXPECT_NEAR(p.y, -0.2f, 1e-5f);
      // Winding was flipped for the mirror, so the CCW face normal still faces +z for all.
      EXPECT_GT(geometricNormal(world.meshes[instance], hit->primitive).z, 0.99f);
    }
  }
}

TEST(RtScene, OcclusionRespectsTheSegment) {
  const WorldGeometry world =
      flattenScene(testgeo::sceneOf({triangleMesh({-1, -1, 0}, {1, -1, 0}, {0, 1, 0})}));
  RtDevice device;
  RtScene rt(device, world);
  const vec3 o(0.f, 0.f, 2.f), down(0.f, 0.f, -1.f);
  EXPECT_TRUE(rt.occluded(o, down, 0.f, 3.f));
  EXPECT_FALSE(rt.occluded(o, down, 0.f, 1.9f));                    // stops before the triangle
  EXPECT_FALSE(rt.occluded(o, -down, 0.f, 10.f));                   // points away
  EXPECT_FALSE(rt.occluded(vec3(5.f, 0.f, 2.f), down, 0.f, 10.f));  // misses beside it
  EXPECT_FALSE(rt.occluded(o, down, 3.f, 1.f));                     // inactive segment
}

TEST(RtScene, BatchAgreesWithSingleRaysAndCountsRays) {
  Scene scene = testgeo::sceneOf(
      {testgeo::uvSphere(vec3(0.f), 1.f, 32, 16), testgeo::groundPlane(5.f, -1.5f)});
  const WorldGeometry world = flattenScene(scene);
  RtDevice device;
  RtScene rt(device, world);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> U(-3.f, 3.f);
  std::vector<OcclusionRay> rays(5000);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    rays[i].origin = vec3(U(rng), U(rng), U(rng));
    rays[i].direction = glm::normalize(vec3(U(rng), U(rng), U(rng)) + vec3(0.01f));
    rays[i].tnear = 0.f;
    rays[i].tfar = i % 50 == 0 ? -1.f : std::abs(U(rng)) * 2.f;  // some inactive
  }
  rt.resetRayCount();
  std::vector<std::uint8_t> batch(rays.size());
  rt.occludedBatch(rays, batch);
  std::size_t active = 0, hits = 0;
  for (const OcclusionRay& r : rays) active += r.tnear <= r.tfar;
  EXPECT_EQ(rt.raysTraced(), active);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const OcclusionRay& r = rays[i];
    EXPECT_EQ(bool(batch[i]), rt.occluded(r.origin, r.direction, r.tnear, r.tfar)) << i;
    hits += batch[i];
  }
  EXPECT_GT(hits, 100u);  // the test exercises both outcomes
  EXPECT_LT(hits, active - 100);
  EXPECT_EQ(rt.raysTraced(), 2 * active);
}

TEST(RtDevice, EmbreeErrorsBecomeErrorsNamingTheCode) {
  RtDevice device;
  EXPECT_NO_THROW(device.check("nothing"));
  // An invalid geometry type is rejected by Embree with RTC_ERROR_INVALID_ARGUMENT.
  RTCGeometry g = rtcNewGeometry(device.handle(), RTCGeometryType(12345));
  EXPECT_EQ(g, nullptr);
  try {
    device.check("creating a bogus geometry");
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("RTC_ERROR_"), std::string::npos) << what;
    EXPECT_NE(what.find("creating a bogus geometry"), std::string::npos) << what;
  }
  EXPECT_NO_THROW(device.check("after the error was taken"));
  EXPECT_EQ(embreeErrorName(RTC_ERROR_OUT_OF_MEMORY), "RTC_ERROR_OUT_OF_MEMORY");
}
}  // namespace DIPTYCH_UNITY_ID
