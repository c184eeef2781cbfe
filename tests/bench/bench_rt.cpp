// Shadow-ray throughput: a tessellated sphere over a plane, one occlusion ray per pixel of a
// 640x480 grid of plane points toward a point light. Reports items_per_second = rays/s.
#include <benchmark/benchmark.h>

#include "engine/rt/shadow_rays.h"
#include "tests/support/rt_test_geometry.h"

using namespace diptych;

namespace {

constexpr int kWidth = 640, kHeight = 480;

struct BenchScene {
  Scene scene;
  WorldGeometry world;
  RtDevice device;
  std::unique_ptr<RtScene> rt;
  std::vector<ShadowReceiver> receivers;
  Light light;
  explicit BenchScene(RTCBuildQuality quality) {
    scene = testgeo::sceneOf(
        {testgeo::uvSphere(vec3(0.f, 2.f, 0.f), 1.f, 256, 128), testgeo::groundPlane(50.f)});
    world = flattenScene(scene);
    rt = std::make_unique<RtScene>(device, world, RtSceneOptions{quality, true});
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x)
        receivers.push_back({vec3(8.f * (float(x) + 0.5f) / kWidth - 4.f, 0.f,
                                  6.f * (float(y) + 0.5f) / kHeight - 3.f),
                             vec3(0, 1, 0), vec3(50.f, 0.f, 50.f)});
    light.position = vec3(0.f, 10.f, 0.f);
  }
};

void BM_OcclusionRays(benchmark::State& state) {
  BenchScene b(RTCBuildQuality(state.range(0)));
  std::vector<OcclusionRay> rays;
  for (const ShadowReceiver& r : b.receivers) rays.push_back(makeShadowRay(b.light, r));
  std::vector<std::uint8_t> occluded(rays.size());
  b.rt->resetRayCount();
  for (auto _ : state) {
    b.rt->occludedBatch(rays, occluded);
    benchmark::DoNotOptimize(occluded.data());
  }
  state.SetItemsProcessed(std::int64_t(b.rt->raysTraced()));
  state.counters["triangles"] = double(b.world.triangleCount());
}

void BM_TraceShadowRays(benchmark::State& state) {  // including ray setup and output
  BenchScene b(RTC_BUILD_QUALITY_HIGH);
  const std::vector<Light> lights{b.light};
  b.rt->resetRayCount();
  for (auto _ : state) benchmark::DoNotOptimize(traceShadowRays(*b.rt, lights, b.receivers));
  state.SetItemsProcessed(std::int64_t(b.rt->raysTraced()));
}

}  // namespace

BENCHMARK(BM_OcclusionRays)
    ->Arg(RTC_BUILD_QUALITY_LOW)
    ->Arg(RTC_BUILD_QUALITY_MEDIUM)
    ->Arg(RTC_BUILD_QUALITY_HIGH)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_TraceShadowRays)->Unit(benchmark::kMillisecond)->UseRealTime();
