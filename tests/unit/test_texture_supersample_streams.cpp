// texture_supersample traces its sub-pixel rays as coherent Embree streams and reads only the
// resolved colour and alpha (resolvedColorAt): its signal against the ray-by-ray producer it
// replaced (TextureSupersamplePass::singleRayPixel: RtScene::intersect + makeSurfacePoint), at
// N = 1 and N = 4 on the textures sample. Embree's packet kernels may round a hit differently
// from the single-ray kernel (a ray through a shared edge can get the other triangle:
// docs/ray-tracing.md, "Coherent rays as Embree streams"), so a pixel may differ; at most 0.1 % of
// them.
#include <gtest/gtest.h>

#include <bit>
#include <cstdio>
#include <limits>
#include <vector>

#include "engine/rt/camera_rays.h"
#include "engine/shading/shading.h"
#include "passes/rt/texture_supersample.h"
#include "passes/slots.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kW = 160, kH = 120;
constexpr double kAllowedDifferent = 0.001;

// textures.json through the built-in hybrid recipe with texture_supersample at N = n.
auto renderSupersampled(int n) {
  Recipe r = defaultHybridRecipe();
  applySlotOverride(
      r, parseSlotOverride("texture_filtering=texture_supersample:samples=" + std::to_string(n)),
      builtinPasses());
  return testing::renderHybridFrame(
      std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/textures.json", kW, kH,
      {"texture_filtering.albedo", "gbuffer.hits"}, r);
}

void expectStreamsMatchSingleRays(int n) {
  const auto f = renderSupersampled(n);
  const CpuImage& albedo = f->output("texture_filtering.albedo");
  const CpuImage& hits = f->output("gbuffer.hits");
  const RtScene& rt = f->world->rtScene();
  const PinholeFrame pinhole(testing::cameraOf(f->scene), kW, kH);
  int covered = 0, different = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      vec4 expected(-1.f);
      if (hits.u(x, y, 0) != 0u) {
        expected = TextureSupersamplePass::singleRayPixel(f->scene, f->world->geometry(), rt,
                                                          pinhole, n, x, y);
        ++covered;
      }
      bool same = true;
      for (int ch = 0; ch < 4; ++ch)
        same = same && std::bit_cast<std::uint32_t>(albedo.f(x, y, ch)) ==
                           std::bit_cast<std::uint32_t>(expected[ch]);
      if (!same) ++different;
    }
  std::printf("N = %d: %d covered pixels, %d differ from the single-ray producer\n", n, covered,
              different);
  EXPECT_GT(covered, kW * kH / 2);
  EXPECT_LE(different, int(kAllowedDifferent * kW * kH));
}

TEST(TextureSupersampleStreams, OneSampleEqualsTheSingleRayProducer) {
  expectStreamsMatchSingleRays(1);
}

TEST(TextureSupersampleStreams, FourByFourSamplesEqualTheSingleRayProducer) {
  expectStreamsMatchSingleRays(4);
}

// The "rays" counter is the rays traced: N^2 per pixel whose centre is covered, none for the
// background (a count of W x H x N^2 would take the background pixels too).
TEST(TextureSupersampleStreams, RaysCounterCountsTheRaysOfCoveredPixelsOnly) {
  constexpr int n = 3;
  const auto f = renderSupersampled(n);
  const CpuImage& hits = f->output("gbuffer.hits");
  int covered = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) covered += hits.u(x, y, 0) != 0u ? 1 : 0;
  ASSERT_GT(covered, 0);
  ASSERT_LT(covered, kW * kH) << "the frame needs background pixels";
  const std::vector<NodeTiming>& timings = f->executor->timings();
  int nodes = 0;
  for (std::size_t i = 0; i < f->graph.nodes.size(); ++i) {
    const GraphNode& node = f->graph.nodes[i];
    if (node.kind != NodeKind::Pass || f->graph.passes[node.pass].type != "texture_supersample")
      continue;
    ++nodes;
    EXPECT_EQ(timings[i].counters.at("rays"), double(covered) * n * n);
  }
  EXPECT_EQ(nodes, 1);
}

// SecondaryFootprint's rays are the tracer's own: the signal is the mean of the N x N sub-pixel
// rays' reflected level-0 lookups (each point casting the ray the Whitted tracer casts there,
// secondaryRay at depth 1; at N = 1 the pixel centre's ray: rt_reflection's own lookup), traced
// here ray by ray in stratum order; and a pixel's footprint alone (secondaryFootprintPixel, the
// ray-by-ray paths' call, x0 = x) is the row's. On textures.json the mirror reflects the
// checkered ground.
void expectFootprintIsTheRayByRayMean(int n) {
  const auto f = renderSupersampled(1);
  const Scene& scene = f->scene;
  const WorldGeometry& geometry = f->world->geometry();
  const RtScene& rt = f->world->rtScene();
  const PinholeFrame pinhole(testing::cameraOf(scene), kW, kH);
  const WhittedTracer tracer(scene, geometry, rt, {});
  std::vector<vec4> colours(kW);
  std::vector<SecondarySignals> signals(kW);
  const std::vector<FootprintTarget> targets(kW, {FootprintTarget::kReflected});
  const auto sameBits = [](const vec4& a, const vec4& b) {
    for (int ch = 0; ch < 4; ++ch)
      if (std::bit_cast<std::uint32_t>(a[ch]) != std::bit_cast<std::uint32_t>(b[ch])) return false;
    return true;
  };
  int filtered = 0, different = 0, pixelDifferent = 0;
  for (int y = 0; y < kH; ++y) {
    const SecondaryFootprint footprint{tracer, targets, signals};
    supersampleTextureRow(scene, geometry, rt, pinhole, {}, n, y, colours, &footprint);
    for (int x = 0; x < kW; ++x) {
      vec4 sum(0.f);
      int count = 0;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const Ray eye =
              pinhole.ray(float(x) + (float(i) + 0.5f) / n, float(y) + (float(j) + 0.5f) / n);
          Hit hit, far;
          if (!CameraRays{rt, scene, geometry}.intersect(eye, hit, false)) continue;
          const SurfacePoint p = makeSurfacePoint(
              scene, geometry, {hit.instance, hit.primitive, hit.u, hit.v, hit.analytic},
              eye.direction);
          WhittedTracer::SecondaryRay s;
          if (shading::hasReflection(p.resolved, false) &&
              tracer.secondaryRay(p, -eye.direction, 1, 0u, nullptr, true, s) &&
              rt.intersect(s.ray, 0.f, std::numeric_limits<float>::infinity(), far, false)) {
            sum += resolvedColorAt(scene, geometry,
                                   {far.instance, far.primitive, far.u, far.v, far.analytic});
            ++count;
          }
        }
      const vec4 expected = count > 0 ? sum / float(count) : vec4(-1.f);
      filtered += count > 0 ? 1 : 0;
      if (!sameBits(signals[std::size_t(x)].reflection, expected)) ++different;
      std::int64_t rays = 0;
      const SecondarySignals alone = secondaryFootprintPixel(
          tracer, scene, geometry, rt, pinhole, n, x, y, targets[std::size_t(x)], rays);
      if (!sameBits(alone.reflection, signals[std::size_t(x)].reflection)) ++pixelDifferent;
      if (count > 0) {
        EXPECT_GE(rays, n * n + count) << x << ", " << y;  // camera + reflected rays
      }
    }
  }
  std::printf("N = %d: %d pixels filtered, %d differ from the ray-by-ray mean, %d alone\n", n,
              filtered, different, pixelDifferent);
  EXPECT_GT(filtered, kW * kH / 50);
  EXPECT_LE(different, int(kAllowedDifferent * kW * kH));
  EXPECT_LE(pixelDifferent, int(kAllowedDifferent * kW * kH));
}

TEST(TextureSupersampleStreams, SecondaryFootprintOfOneSampleIsTheCentreRaysReflectedLookup) {
  expectFootprintIsTheRayByRayMean(1);
}

TEST(TextureSupersampleStreams, SecondaryFootprintIsTheMeanOfTheSubPixelRaysReflectedLookups) {
  expectFootprintIsTheRayByRayMean(2);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
