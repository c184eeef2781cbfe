// The Whitted tracer's tiled entry points (engine/rt/whitted_tile.cpp) against its ray-by-ray
// recursion: a tile of primary rays traced as an Embree stream (RtScene::intersectTile) and
// shaded by radianceTile, whose shadow rays go as one stream, must give radiance()'s result bit
// for bit, and count the same rays; tracedTile must give reflected() and transmitted(). (Embree's
// packet kernels may round a ray through a shared triangle edge differently from its single-ray
// ones; none of these frames has such a ray, so a difference here is ours.) The
// scenes cover analytic spheres, a glass volume, point, spot, directional and area lights
// (stratified samples), a checker texture, and ray cones.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "engine/graph/render_world.h"
#include "engine/rt/whitted.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/load.h"
#include "engine/shading/shading.h"
#include "tests/support/test_paths.h"

using namespace diptych;

namespace {

constexpr int kW = 96, kH = 72;

Scene sample(const std::string& name) {
  return loadScene(DIPTYCH_SAMPLES_DIR + "/scenes/" + name);
}

// The primary rays of row y, traced as one stream; hits[i] null on a miss.
void traceRow(const RtScene& rt, const Scene& scene, int y, int x0, int n, Ray* rays, Hit* hits,
              const Hit** found) {
  RTCRayHit tile[WhittedTracer::kMaxTile];
  for (int i = 0; i < n; ++i) {
    rays[i] = primaryRay(scene.camera, kW, kH, float(x0 + i) + 0.5f, float(y) + 0.5f);
    setEmbreeRay(tile[i].ray, rays[i].origin, rays[i].direction, 0.f,
                 std::numeric_limits<float>::infinity());
    tile[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
    tile[i].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  }
  rt.intersectTile({tile, std::size_t(n)}, true);
  for (int i = 0; i < n; ++i) found[i] = rt.hitOf(tile[i], hits[i], true) ? &hits[i] : nullptr;
}

// Every pixel of a kW x kH frame both ways; hitCount: the number of pixels that hit something.
void expectTileEqualsRayByRay(const Scene& scene, WhittedSettings settings, bool cones,
                              int& hitCount) {
  RenderWorld world(scene);
  const RtScene& rt = world.rtScene();
  const WhittedTracer tiled(scene, world.geometry(), rt, settings);
  const WhittedTracer single(scene, world.geometry(), rt, settings);
  const RayCone primary{0.f, pixelSpreadAngle(scene.camera, kH)};
  constexpr int kTile = int(WhittedTracer::kMaxTile);
  hitCount = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x0 = 0; x0 < kW; x0 += kTile) {
      const int n = std::min(kTile, kW - x0);
      Ray rays[kTile];
      Hit hits[kTile];
      const Hit* found[kTile];
      std::uint32_t seeds[kTile];
      const RayCone* coneOf[kTile];
      vec3 out[kTile];
      traceRow(rt, scene, y, x0, n, rays, hits, found);
      for (int i = 0; i < n; ++i) {
        seeds[i] = std::uint32_t(y * kW + x0 + i);
        coneOf[i] = &primary;
        // The stream's hit is rtcIntersect1's, field by field.
        const auto one = rt.intersect(rays[i], 0.f, std::numeric_limits<float>::infinity());
        ASSERT_EQ(one.has_value(), found[i] != nullptr);
        if (one) {
          ++hitCount;
          EXPECT_EQ(one->instance, hits[i].instance);
          EXPECT_EQ(one->primitive, hits[i].primitive);
          EXPECT_EQ(one->u, hits[i].u);
          EXPECT_EQ(one->v, hits[i].v);
          EXPECT_EQ(one->t, hits[i].t);
          EXPECT_EQ(one->Ng, hits[i].Ng);
        }
      }
      const std::size_t m = std::size_t(n);
      tiled.radianceTile({rays, m}, {found, m}, {seeds, m}, 1, {coneOf, cones ? m : 0}, {out, m});
      for (int i = 0; i < n; ++i) {
        const vec3 expected = single.radiance(rays[i], 1, seeds[i], cones ? &primary : nullptr);
        ASSERT_EQ(out[i], expected) << "pixel " << x0 + i << ", " << y;
      }
    }
  }
  EXPECT_EQ(tiled.raysTraced(), single.raysTraced());
}

}  // namespace

TEST(WhittedTile, RadianceTileEqualsRayByRayOnWhitted) {
  // Analytic mirror and glass spheres over a checker, one point light.
  int hits = 0;
  expectTileEqualsRayByRay(sample("whitted.json"), {5, 16, false}, false, hits);
  EXPECT_GT(hits, kW * kH / 2);
}

TEST(WhittedTile, RadianceTileEqualsRayByRayWithAreaLightSamples) {
  // cornell.json's area light: 4 stratified shadow rays per point, jittered by the pixel seed.
  int hits = 0;
  expectTileEqualsRayByRay(sample("cornell.json"), {5, 4, false}, false, hits);
  EXPECT_GT(hits, kW * kH / 2);
}

TEST(WhittedTile, RadianceTileEqualsRayByRayWithRayConesAndSeveralLights) {
  // Directional and spot lights, glass with a volume, a box, a cylinder; texture LOD by cone.
  int hits = 0;
  expectTileEqualsRayByRay(sample("techniques.json"), {5, 16, true}, true, hits);
  EXPECT_GT(hits, kW * kH / 2);
}

TEST(WhittedTile, TracedTileEqualsReflectedAndTransmitted) {
  const Scene scene = sample("techniques.json");
  RenderWorld world(scene);
  const WhittedTracer tracer(scene, world.geometry(), world.rtScene(), {5, 16, true});
  std::vector<WhittedTracer::SecondaryRay> rays;
  std::vector<vec3> expected;
  const RayCone cone{0.01f, pixelSpreadAngle(scene.camera, kH)};
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const Ray eye = primaryRay(scene.camera, kW, kH, float(x) + 0.5f, float(y) + 0.5f);
      const auto hit = world.rtScene().intersect(eye, 0.f, std::numeric_limits<float>::infinity());
      if (!hit) continue;
      const SurfacePoint p = makeSurfacePoint(
          scene, world.geometry(), {hit->instance, hit->primitive, hit->u, hit->v, hit->analytic},
          eye.direction);
      const std::uint32_t seed = std::uint32_t(y * kW + x);
      for (const bool reflection : {true, false}) {
        if (reflection ? !shading::hasReflection(p.resolved, false)
                       : !shading::hasTransmission(p.resolved))
          continue;
        WhittedTracer::SecondaryRay s;
        ASSERT_TRUE(tracer.secondaryRay(p, -eye.direction, 1, seed, &cone, reflection, s));
        EXPECT_EQ(s.depth, 2);
        rays.push_back(s);
        expected.push_back(reflection ? tracer.reflected(p, -eye.direction, 1, seed, &cone)
                                      : tracer.transmitted(p, -eye.direction, 1, seed, &cone));
      }
    }
  }
  ASSERT_GT(rays.size(), 100u);  // more than one tile of kMaxTile
  std::vector<vec3> out(rays.size());
  tracer.tracedTile(rays, out);
  for (std::size_t i = 0; i < rays.size(); ++i) ASSERT_EQ(out[i], expected[i]) << "ray " << i;
  // At the last depth there is no secondary ray (its radiance is 0).
  WhittedTracer::SecondaryRay s;
  const Ray eye = primaryRay(scene.camera, kW, kH, kW / 2.f, kH / 2.f);
  const auto hit = world.rtScene().intersect(eye, 0.f, std::numeric_limits<float>::infinity());
  ASSERT_TRUE(hit.has_value());
  const SurfacePoint p = makeSurfacePoint(
      scene, world.geometry(), {hit->instance, hit->primitive, hit->u, hit->v, hit->analytic},
      eye.direction);
  EXPECT_FALSE(tracer.secondaryRay(p, -eye.direction, 5, 0u, nullptr, true, s));
}
