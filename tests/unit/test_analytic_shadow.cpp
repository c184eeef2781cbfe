// The hybrid frame (gbuffer -> rt_shadows -> shade) against an analytic answer: the shadow of a
// sphere (radius r = 1, centre at height c = 2) on the plane y = 0 cast by a point light at
// height H = 10 straight above the centre is the disc of radius
//   R = H r / sqrt((H - c)^2 - r^2) = 10 / sqrt(63) = 1.25988
// (the light's tangent cone to the sphere, cut by the plane). samples/scenes/shadow-sphere.json.
//
// The shadow radius is measured from the pixels: each plane pixel's world position is rebuilt
// from the G-buffer (u, v); the largest radius of a shadowed pixel and the smallest radius of a
// lit pixel bracket the boundary.
//
// The sphere is analytic on the exact side ("geometry": "analytic": Embree user geometry), so
// every pixel must be classified exactly, up to float noise:
//   - no shadowed pixel beyond R + eps, no lit pixel inside R - eps, where eps is the shift of
//     the boundary caused by the shadow ray's robust origin offset (raised by delta above the
//     plane, the tangent cone's radius shrinks by delta r / sqrt((H - c)^2 - r^2); delta is
//     measured from offsetRayOrigin itself) plus 1e-5 R for the float ray;
//   - and the boundary pixels exist: max shadowed >= R - footprint, min lit <= R + footprint
//     (footprint = the largest distance between neighbouring plane pixels within 5 % of R).
// Before (a tessellated sphere, 256 x 128) both sides had tolerance footprint + 1.9e-4 (the
// tessellation deficit); the inner side is now eps, measured 1.5e-5 with today's offset.
// Shadowed means visibility 0 for the single light; the shade pass must then give the plane no
// light at all (ambient and emission are 0 in this scene), lit plane pixels some.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <numbers>
#include <vector>

#include "engine/rt/ray_offset.h"
#include "passes/common/hits_texel.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr double kH = 10.0, kC = 2.0, kR = 1.0;

double shadowRadius(double sphereRadius) {
  return kH * sphereRadius / std::sqrt((kH - kC) * (kH - kC) - sphereRadius * sphereRadius);
}

TEST(AnalyticShadow, SphereOverPlaneShadowDiscHasTheExactRadius) {
  const int w = 512, h = 512;
  const auto file = std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes" / "shadow-sphere.json";
  auto frame =
      testing::renderHybridFrame(file, w, h, {"gbuffer.hits", "shadows.visibility", "shade.color"});
  ASSERT_FALSE(frame->pass("shadows")->culled);
  ASSERT_EQ(frame->scene.lights.size(), 1u);
  ASSERT_EQ(frame->scene.lights[0].position, vec3(0.f, float(kH), 0.f));

  int plane = -1;
  for (std::size_t i = 0; i < frame->scene.instances.size(); ++i)
    if (frame->scene.instances[i].name == "ground") plane = int(i);
  ASSERT_GE(plane, 0) << "shadow-sphere.json has no instance named 'ground'";

  const CpuImage& gbuffer = frame->output("gbuffer.hits");
  const CpuImage& shadows = frame->output("shadows.visibility");
  const CpuImage& color = frame->output("shade.color");
  ASSERT_EQ(shadows.desc.layers, 1);
  const WorldMesh& mesh = frame->world->geometry().meshes.at(std::size_t(plane));

  // World position of every plane pixel (NaN elsewhere).
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<vec3> position(std::size_t(w) * h, vec3(nan));
  // The hybrid's G-buffer is a visibility buffer: the point the shadow pass used is exactTexel's.
  const PinholeFrame pinhole(frame->graph.frame.camera, w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (const auto hit = exactTexel(gbuffer, frame->world->geometry(), pinhole, x, y,
                                      &frame->world->rtScene());
          hit && hit->instance == plane)
        position[std::size_t(y) * w + x] =
            interpolatePosition(mesh, hit->primitive, hit->u, hit->v);
  auto at = [&](int x, int y) { return position[std::size_t(y) * w + x]; };
  auto onPlane = [&](int x, int y) { return !std::isnan(at(x, y).x); };
  auto radius = [&](int x, int y) { return std::hypot(double(at(x, y).x), double(at(x, y).z)); };

  const double R = shadowRadius(kR);
  for (std::size_t i = 0; i < frame->scene.instances.size(); ++i) {
    if (frame->scene.instances[i].name == "ball") {
      ASSERT_TRUE(frame->world->geometry().meshes[i].analytic) << "the ball must be analytic";
    }
  }
  // The largest upward offset of a shadow-ray origin over the plane pixels.
  double delta = 0.0;
  const vec3 magnitude = vertexMagnitude(mesh.positions[0], mesh.positions[1], mesh.positions[2]);
  for (const vec3& p : position)
    if (!std::isnan(p.x))
      delta = std::max(delta, double(offsetRayOrigin(p, vec3(0, 1, 0), magnitude).y - p.y));
  const double eps = delta * kR / std::sqrt((kH - kC) * (kH - kC) - kR * kR) + 1e-5 * R;

  double maxShadowed = 0.0, minLit = 1e30, footprint = 0.0;
  int planePixels = 0, shadowed = 0, lit = 0, innerLit = 0, outerShadowed = 0, badShade = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!onPlane(x, y)) continue;
      ++planePixels;
      const double rad = radius(x, y);
      const float vis = shadows.f(x, y, 0);
      ASSERT_TRUE(vis == 0.f || vis == 1.f) << "visibility " << vis << " at " << x << "," << y;
      const float luminance = color.f(x, y, 0) + color.f(x, y, 1) + color.f(x, y, 2);
      if (vis == 0.f) {
        ++shadowed;
        maxShadowed = std::max(maxShadowed, rad);
        outerShadowed += rad > 1.1 * R;
        badShade += luminance != 0.f;
      } else {
        ++lit;
        minLit = std::min(minLit, rad);
        innerLit += rad < 0.9 * R;
        badShade += !(luminance > 0.f);
      }
      if (std::abs(rad - R) < 0.05 * R) {
        if (x + 1 < w && onPlane(x + 1, y))
          footprint = std::max(footprint, double(glm::length(at(x + 1, y) - at(x, y))));
        if (y + 1 < h && onPlane(x, y + 1))
          footprint = std::max(footprint, double(glm::length(at(x, y + 1) - at(x, y))));
      }
    }
  }
  std::printf(
      "[analytic shadow] %dx%d: plane pixels %d (shadowed %d, lit %d); R = %.6f, max shadowed "
      "radius %.6f (%+.2e), min lit radius %.6f (%+.2e); footprint %.4f, eps %.2e (offset "
      "%.2e)\n",
      w, h, planePixels, shadowed, lit, R, maxShadowed, maxShadowed - R, minLit, minLit - R,
      footprint, eps, delta);
  ::testing::Test::RecordProperty("max_shadowed_radius", std::to_string(maxShadowed));
  ::testing::Test::RecordProperty("min_lit_radius", std::to_string(minLit));
  ::testing::Test::RecordProperty("eps", std::to_string(eps));

  // A disc of radius R on this view covers thousands of pixels: without them the bracket below
  // would be meaningless.
  ASSERT_GT(shadowed, 1000);
  ASSERT_GT(lit, 1000);
  ASSERT_GT(footprint, 0.0);
  EXPECT_LT(footprint, 0.05) << "the boundary must be resolved finely for the bound to mean much";
  EXPECT_LE(maxShadowed, R + eps) << "a pixel outside the exact shadow is shadowed";
  EXPECT_GE(minLit, R - eps) << "a pixel inside the exact shadow is lit";
  EXPECT_GE(maxShadowed, R - footprint);
  EXPECT_LE(minLit, R + footprint);
  EXPECT_EQ(innerLit, 0) << "plane pixels inside 0.9 R must be shadowed";
  EXPECT_EQ(outerShadowed, 0) << "plane pixels outside 1.1 R must be lit";
  EXPECT_EQ(badShade, 0) << "shade must give shadowed plane pixels 0 and lit ones > 0";
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
