// The Whitted tracer's tiled entry points (engine/rt/whitted_tile.cpp) against its ray-by-ray
// recursion: radianceTile, given a tile's closest hits (rtcIntersect1's here, so that the check
// is of our arithmetic alone), must give radiance()'s result bit for bit and count the same rays;
// tracedTile must give reflected() and transmitted() (rt_distributed's tiles:
// test_distributed_tiles.cpp). Hits from RtScene::intersectRays (Embree's
// packet kernels) may round differently from its single-ray ones at a shared triangle edge, and
// the packets' width depends on the CPU (AVX2 or AVX-512): those comparisons allow a stated
// budget. The scenes cover analytic spheres, a glass volume, point, spot, directional and area
// lights (stratified samples), a checker texture, ray cones, an alpha-masked mesh (Embree's
// filter function) and an instanced mesh (instID).
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <string>
#include <vector>

#include "engine/core/check.h"
#include "engine/graph/render_world.h"
#include "engine/rt/whitted.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/load.h"
#include "engine/shading/shading.h"
#include "tests/support/rt_test_geometry.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

constexpr int kW = 96, kH = 72;

Scene sample(const std::string& name) {
  return loadScene(DIPTYCH_SAMPLES_DIR + "/scenes/" + name);
}

// A checker-alpha quad (alphaMode MASK: Embree's filter function) over a ground plane, and one
// sphere mesh placed three times (built once and instanced: hits name their instance by instID),
// under a point light whose shadow rays pass through the quad's holes.
Scene maskedAndInstanced() {
  Mesh quad = testgeo::groundPlane(1.f, 0.5f);
  quad.material = 0;
  const Mesh sphere = testgeo::uvSphere(vec3(0.f), 0.4f, 24, 12);
  Scene s = testgeo::sceneOf({testgeo::groundPlane(4.f, 0.f), quad, sphere});
  s.instances[2].transform = glm::translate(mat4(1.f), vec3(-1.5f, 0.4f, 0.f));
  s.instances.push_back(Instance{"copy 1", 2, glm::translate(mat4(1.f), vec3(1.5f, 0.4f, 0.f))});
  s.instances.push_back(Instance{"copy 2", 2, glm::translate(mat4(1.f), vec3(0.f, 0.9f, 1.2f))});
  Texture t;
  t.name = "checker alpha";
  t.image = Image(8, 8, 4, 1.f);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) t.image.at(x, y, 3) = (x + y) % 2 == 0 ? 1.f : 0.f;
  t.minFilter = t.magFilter = FilterMode::Nearest;
  s.textures.push_back(t);
  Material m;
  m.name = "mask";
  m.alphaMode = AlphaMode::Mask;
  m.colorTexture = 0;
  s.materials.push_back(m);
  Light l;
  l.type = LightType::Point;
  l.position = vec3(0.3f, 4.f, 0.2f);
  l.intensity = 20.f;
  s.lights.push_back(l);
  s.camera.position = vec3(0.f, 3.f, 3.5f);
  s.camera.target = vec3(0.f, 0.f, 0.f);
  s.hasCamera = true;
  return s;
}

// The primary rays of row y and their closest hits ray by ray (rtcIntersect1); null: a miss.
void traceRow(const RtScene& rt, const Scene& scene, int y, int x0, int n, Ray* rays, Hit* hits,
              const Hit** found) {
  for (int i = 0; i < n; ++i) {
    rays[i] = primaryRay(scene.camera, kW, kH, float(x0 + i) + 0.5f, float(y) + 0.5f);
    found[i] = rt.intersect(rays[i], 0.f, std::numeric_limits<float>::infinity(), hits[i], true)
                   ? &hits[i]
                   : nullptr;
  }
}

// Every pixel of a kW x kH frame both ways; hitCount: the number of pixels that hit something.
// With settings.streams off the tile's recursion finds its hits with rtcIntersect1, as
// radiance() does: bit for bit, the same ray count. With streams (the default) its secondary
// rays' hits come from Embree's packet kernels, which may round differently at a shared edge or
// break a tie between coplanar faces the other way (techniques.json's glass box stands on the
// ground: a ray inside it meets its bottom face and the ground at the same t, and a packet gave
// the ground where rtcIntersect1 gave the box; 14 of 6,912 pixels, by up to 0.04): at most 1% of
// the pixels may differ (streamDiffer returns how many did).
void expectTileEqualsRayByRay(const Scene& scene, WhittedSettings settings, bool cones,
                              int& hitCount, int* streamDiffer = nullptr) {
  RenderWorld world(scene);
  const RtScene& rt = world.rtScene();
  WhittedSettings exact = settings, streamed = settings;
  exact.streams = false;
  streamed.streams = true;
  const WhittedTracer tiled(scene, world.geometry(), rt, exact);
  const WhittedTracer tiledStreams(scene, world.geometry(), rt, streamed);
  const WhittedTracer single(scene, world.geometry(), rt, settings);
  const RayCone primary{0.f, pixelSpreadAngle(scene.camera, kH)};
  constexpr int kTile = int(WhittedTracer::kMaxTile);
  hitCount = 0;
  int differ = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x0 = 0; x0 < kW; x0 += kTile) {
      const int n = std::min(kTile, kW - x0);
      Ray rays[kTile];
      Hit hits[kTile];
      const Hit* found[kTile];
      std::uint32_t seeds[kTile];
      const RayCone* coneOf[kTile];
      vec3 out[kTile], outStreams[kTile];
      traceRow(rt, scene, y, x0, n, rays, hits, found);
      for (int i = 0; i < n; ++i) {
        seeds[i] = std::uint32_t(y * kW + x0 + i);
        coneOf[i] = &primary;
        hitCount += found[i] ? 1 : 0;
      }
      const std::size_t m = std::size_t(n);
      tiled.radianceTile({rays, m}, {found, m}, {seeds, m}, 1, {coneOf, cones ? m : 0}, {out, m});
      tiledStreams.radianceTile({rays, m}, {found, m}, {seeds, m}, 1, {coneOf, cones ? m : 0},
                                {outStreams, m});
      for (int i = 0; i < n; ++i) {
        const vec3 expected = single.radiance(rays[i], 1, seeds[i], cones ? &primary : nullptr);
        ASSERT_EQ(out[i], expected) << "pixel " << x0 + i << ", " << y;
        differ += outStreams[i] == expected ? 0 : 1;
      }
    }
  }
  EXPECT_EQ(tiled.raysTraced(), single.raysTraced());
  EXPECT_LE(differ, kW * kH / 100) << "pixels whose streamed tile differs";
  if (streamDiffer) *streamDiffer = differ;
}

// intersectRays' hits (streams of 64) against intersect's, ray by ray, over a kW x kH frame.
// Budget: at most 0.1% of the rays differ in any field, and those only as a shared edge or the
// packet kernels' rounding can make them: both hit, at t within 1e-4 relative (the same point,
// maybe the neighbouring triangle). A hit against a miss is never allowed (robust traversal is
// watertight). hitsPerInstance counts the stream's hits.
void expectStreamHitsWithinBudget(const Scene& scene, std::vector<int>& hitsPerInstance) {
  RenderWorld world(scene);
  const RtScene& rt = world.rtScene();
  std::vector<Ray> rays;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      rays.push_back(primaryRay(scene.camera, kW, kH, float(x) + 0.5f, float(y) + 0.5f));
  std::vector<Hit> hits(rays.size());
  std::vector<const Hit*> found(rays.size());
  rt.intersectRays(rays, hits, found, true);
  hitsPerInstance.assign(world.geometry().meshes.size(), 0);
  int differ = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const auto one = rt.intersect(rays[i], 0.f, std::numeric_limits<float>::infinity());
    ASSERT_EQ(one.has_value(), found[i] != nullptr) << "ray " << i;
    if (!one) continue;
    ASSERT_EQ(found[i], &hits[i]);
    const Hit& h = hits[i];
    ++hitsPerInstance[std::size_t(h.instance)];
    if (one->instance == h.instance && one->primitive == h.primitive && one->u == h.u &&
        one->v == h.v && one->t == h.t && one->Ng == h.Ng)
      continue;
    ++differ;
    EXPECT_NEAR(h.t, one->t, 1e-4f * one->t) << "ray " << i;
  }
  EXPECT_LE(differ, int(rays.size()) / 1000) << "of " << rays.size() << " rays";
}

TEST(WhittedTile, RadianceTileEqualsRayByRayOnWhitted) {
  // Analytic mirror and glass spheres over a checker, one point light.
  int hits = 0, differ = -1;
  expectTileEqualsRayByRay(sample("whitted.json"), {5, 16, false}, false, hits, &differ);
  EXPECT_GT(hits, kW * kH / 2);
  // Its spheres are user geometry (our callback's arithmetic, one ray or a packet) and its
  // ground has no edge in view: the streamed tiles are bit for bit too.
  EXPECT_EQ(differ, 0);
  // Deeper than kBatchedDepths: the levels past it go ray by ray inside the tile.
  ASSERT_LT(WhittedTracer::kBatchedDepths, 12);
  expectTileEqualsRayByRay(sample("whitted.json"), {12, 16, false}, false, hits, &differ);
  EXPECT_EQ(differ, 0);
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

TEST(WhittedTile, RadianceTileEqualsRayByRayThroughAlphaMaskAndInstances) {
  // Shadow streams through the filter function's holes, and hits on prototype instances.
  const Scene scene = maskedAndInstanced();
  int hits = 0;
  expectTileEqualsRayByRay(scene, {5, 16, false}, false, hits);
  EXPECT_GT(hits, kW * kH / 2);
}

TEST(WhittedTile, StreamHitsMatchSingleRayHitsWithinBudget) {
  std::vector<int> perInstance;
  for (const char* file : {"whitted.json", "cornell.json", "techniques.json"}) {
    SCOPED_TRACE(file);
    expectStreamHitsWithinBudget(sample(file), perInstance);
  }
  // Streams of 64 through the alpha filter and instID: the scene's every instance is hit (the
  // plane through the quad's holes too), and the RtScene really filters and instances.
  const Scene scene = maskedAndInstanced();
  {
    RenderWorld world(scene);
    EXPECT_EQ(world.rtScene().alphaMaskedGeometries(), 1);
    EXPECT_EQ(world.rtScene().instancedGeometries(), 3);
  }
  expectStreamHitsWithinBudget(scene, perInstance);
  ASSERT_EQ(perInstance.size(), 5u);
  for (std::size_t i = 0; i < perInstance.size(); ++i)
    EXPECT_GT(perInstance[i], 20) << "instance " << i;
}

TEST(WhittedTile, RadianceTileRejectsDepthsOutsideTheRecursion) {
  // radiance() traces nothing beyond maxDepth; a tile at such a depth is a caller's error.
  const Scene scene = sample("whitted.json");
  RenderWorld world(scene);
  const WhittedTracer tracer(scene, world.geometry(), world.rtScene(), {3, 4, false});
  Ray rays[1];
  Hit hits[1];
  const Hit* found[1];
  traceRow(world.rtScene(), scene, kH / 2, kW / 2, 1, rays, hits, found);
  const std::uint32_t seeds[1] = {0u};
  vec3 out[1];
  for (const int depth : {0, 4}) {
    EXPECT_THROW(tracer.radianceTile(rays, found, seeds, depth, {}, out), InternalError)
        << "depth " << depth;
  }
  EXPECT_NO_THROW(tracer.radianceTile(rays, found, seeds, 3, {}, out));
  EXPECT_EQ(out[0], tracer.radiance(rays[0], 3, 0u));
}

TEST(WhittedTile, TracedTileEqualsReflectedAndTransmitted) {
  Scene scene = sample("techniques.json");
  // The glass box rests on the floor: its bottom face and the floor are coplanar, and which of
  // the two a ray reports there depends on the kernel's traversal order, which differs between
  // Embree's single-ray and stream kernels and between ISAs (9 of 741 rays differed on an Intel
  // Xeon, 33 on an AMD EPYC with AVX2). Raised 1 cm there is no tie, and nothing else differs.
  for (Instance& instance : scene.instances)
    if (instance.name == "blue glass box")
      instance.transform = glm::translate(mat4(1.f), vec3(0.f, 0.01f, 0.f)) * instance.transform;
  RenderWorld world(scene);
  // Without streams (rtcIntersect1 at every level) bit for bit; with them too but for a rounding
  // difference of a packet kernel (none on AVX2; a budget of 1% for other ISAs).
  const WhittedTracer tracer(scene, world.geometry(), world.rtScene(), {5, 16, true, false});
  const WhittedTracer streamed(scene, world.geometry(), world.rtScene(), {5, 16, true, true});
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
  streamed.tracedTile(rays, out);
  int differ = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) differ += out[i] == expected[i] ? 0 : 1;
  EXPECT_LE(differ, int(rays.size()) / 100) << "streamed rays that differ, of " << rays.size();
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
}  // namespace DIPTYCH_UNITY_ID
