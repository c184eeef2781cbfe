// Shadow rays against analytic truths: the shadow disc of a sphere on a plane.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/rt/shadow_rays.h"
#include "engine/rt/surface_point.h"
#include "tests/support/rt_test_geometry.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

constexpr float kH = 10.f, kC = 2.f, kR = 1.f;  // light height, sphere centre height, radius

struct SphereOverPlane {
  Scene scene;
  WorldGeometry world;
  RtDevice device;
  std::unique_ptr<RtScene> rt;
  SphereOverPlane() {
    // 256 segments: the inscribed silhouette is within 1 - cos(pi/256) < 1e-4 of the sphere.
    scene = testgeo::sceneOf(
        {testgeo::uvSphere(vec3(0.f, kC, 0.f), kR, 256, 128), testgeo::groundPlane(50.f)});
    world = flattenScene(scene);
    rt = std::make_unique<RtScene>(device, world);
  }
};

// Receivers on the plane at radius `radius`, `count` angles; found by tracing rays up from
// below the plane, so positions and normals come from real hits (and face away from the light).
std::vector<ShadowReceiver> ringFromBelow(const SphereOverPlane& s, float radius, int count) {
  std::vector<ShadowReceiver> out;
  for (int i = 0; i < count; ++i) {
    const float phi = 2.f * std::numbers::pi_v<float> * (float(i) + 0.5f) / float(count);
    const Ray ray{vec3(radius * std::cos(phi), -3.f, radius * std::sin(phi)), vec3(0, 1, 0)};
    const auto hit = s.rt->intersect(ray, 0.f, 100.f);
    EXPECT_TRUE(hit && hit->instance == 1);
    const SurfacePoint p = makeSurfacePoint(
        s.scene, s.world, {hit->instance, hit->primitive, hit->u, hit->v}, ray.direction);
    EXPECT_FALSE(p.frontFacing);
    EXPECT_LT(p.geometricNormal.y, -0.99f);
    out.push_back({p.position, p.geometricNormal, p.positionMagnitude});
  }
  return out;
}

TEST(ShadowRays, SphereShadowDiscUnderPointLightMatchesAnalyticRadius) {
  SphereOverPlane s;
  const float R = kH * kR / std::sqrt((kH - kC) * (kH - kC) - kR * kR);
  EXPECT_NEAR(R, 1.25988f, 1e-5f);
  Light light;
  light.type = LightType::Point;
  light.position = vec3(0.f, kH, 0.f);
  const std::vector<Light> lights{light};
  const int n = 720;
  for (const auto& [factor, expected] : {std::pair{0.95f, 0.f}, std::pair{1.05f, 1.f}}) {
    // Receivers given directly on the plane, normal up...
    std::vector<ShadowReceiver> direct;
    for (int i = 0; i < n; ++i) {
      const float phi = 2.f * std::numbers::pi_v<float> * float(i) / float(n);
      direct.push_back({vec3(factor * R * std::cos(phi), 0.f, factor * R * std::sin(phi)),
                        vec3(0, 1, 0), vec3(0.f)});
    }
    // ...and from real hits on the plane's back side (the ray must leave from the lit side).
    std::vector<ShadowReceiver> hits = ringFromBelow(s, factor * R, n);
    for (const auto* receivers : {&direct, &hits}) {
      const std::vector<float> vis = traceShadowRays(*s.rt, lights, *receivers);
      ASSERT_EQ(vis.size(), std::size_t(n));
      for (int i = 0; i < n; ++i) ASSERT_EQ(vis[i], expected) << "factor " << factor << " i " << i;
    }
  }
}

TEST(ShadowRays, DirectionalLightCastsADiscOfTheSphereRadiusAndFlagsAreHonoured) {
  SphereOverPlane s;
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = vec3(0.f, -1.f, 0.f);
  Light noShadows = sun;
  noShadows.castsShadows = false;
  Light spot;
  spot.type = LightType::Spot;
  spot.position = vec3(0.f, kH, 0.f);
  spot.direction = vec3(0.f, -1.f, 0.f);
  const std::vector<Light> lights{sun, noShadows, spot};
  const std::vector<ShadowReceiver> receivers{
      {vec3(0.95f * kR, 0.f, 0.f), vec3(0, 1, 0), vec3(0.f)},
      {vec3(0.f, 0.f, 1.05f * kR), vec3(0, 1, 0), vec3(0.f)},
      {vec3(0.f, 0.f, 0.f), vec3(0, 1, 0), vec3(0.f)},
      // On the sphere's top, facing the light: its own geometry must not shadow it.
      {vec3(0.f, kC + kR, 0.f), vec3(0, 1, 0), vec3(0.f)},
  };
  const std::vector<float> v = traceShadowRays(*s.rt, lights, receivers);
  const std::vector<float> expected{0, 1, 0, 1,   // sun
                                    1, 1, 1, 1,   // castsShadows == false
                                    0, 0, 0, 1};  // spot at H: its shadow disc (R 1.26) covers 1.05
  EXPECT_EQ(v, expected);
}

TEST(ShadowRays, AreaLightsAreTracedTowardTheirCentre) {
  SphereOverPlane s;
  Light quad;
  quad.type = LightType::QuadArea;
  quad.position = vec3(0.f, kH, 0.f);
  quad.edgeU = vec3(1.f, 0.f, 0.f);
  quad.edgeV = vec3(0.f, 0.f, 1.f);
  const OcclusionRay ray = makeShadowRay(quad, {vec3(3.f, 0.f, 0.f), vec3(0, 1, 0), vec3(0.f)});
  EXPECT_GT(ray.tfar, 0.f);
  const vec3 end = ray.origin + ray.tfar * ray.direction;
  EXPECT_LT(glm::length(end - quad.position), 1e-4f);
  EXPECT_GT(glm::length(end - quad.position), 0.f);  // stops short
}

// The contact test's distance (docs/shadow-bias.md §3): along the shadow ray to the first
// occluder. Under a sun overhead, the ground point below the sphere's centre meets the sphere's
// bottom at kC - kR; a point off the sphere's shadow, and a disabled light, meet nothing.
TEST(ShadowRays, OccluderDistanceIsTheHitDistanceAlongTheShadowRay) {
  SphereOverPlane s;
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = vec3(0.f, -1.f, 0.f);
  const ShadowReceiver under{vec3(0.f), vec3(0, 1, 0), vec3(0.f)};
  const ShadowReceiver beside{vec3(3.f * kR, 0.f, 0.f), vec3(0, 1, 0), vec3(0.f)};
  // The tessellated sphere's lowest vertex is its pole: kC - kR up to float rounding.
  EXPECT_NEAR(occluderDistance(*s.rt, sun, under), kC - kR, 1e-4f);
  EXPECT_TRUE(std::isinf(occluderDistance(*s.rt, sun, beside)));
  Light off = sun;
  off.castsShadows = false;
  EXPECT_TRUE(std::isinf(occluderDistance(*s.rt, off, under)));
  // A point light: the distance is along the segment to the light, which stops short of it.
  Light point;
  point.type = LightType::Point;
  point.position = vec3(0.f, kH, 0.f);
  EXPECT_NEAR(occluderDistance(*s.rt, point, under), kC - kR, 1e-4f);
}
}  // namespace DIPTYCH_UNITY_ID
