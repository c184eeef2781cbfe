// Path-tracer throughput (rt_path, passes/rt/rt_path.h) on the sample scenes at 320 x 240.
//
// Method: a CPU-only graph with one rt_path pass at spp = 1 (one progressive pass: one path per
// pixel) is compiled, the world and executor are created once, one warm-up frame builds the
// Embree BVH, then each benchmark iteration is one GraphExecutor::runFrame(). Counters:
//   samples/s  pixel samples (paths) per second of wall time
//   rays/s     intersection + shadow rays per second (the pass's "rays" counter)
//   rays/sample
// Wall clock on a shared machine: reported, never asserted (docs/reference-renderers.md).
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "engine/graph/executor.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

using namespace diptych;

namespace {

constexpr int kWidth = 320, kHeight = 240;

void BM_PathTracer(benchmark::State& state, const std::string& sceneFile) {
  const Scene scene = loadScene(std::string(DIPTYCH_SAMPLES_DIR) + "/scenes/" + sceneFile);
  Recipe recipe;
  recipe.file = "<bench_path>";
  recipe.passes = {{.name = "path", .type = "rt_path", .params = {{"spp", 1}}, .place = "bench"}};
  recipe.outputs = {"path.color"};
  const CompiledGraph graph =
      compileGraph(recipe, builtinPasses(), scene, {kWidth, kHeight, scene.camera});
  RenderWorld world(scene);
  GraphExecutor executor(graph, world);
  executor.runFrame();  // warm-up: builds the BVH
  double samples = 0, rays = 0;
  for (auto _ : state) {
    executor.runFrame();
    const auto& counters = executor.timings().front().counters;
    samples += counters.at("samples");
    rays += counters.at("rays");
  }
  state.counters["samples/s"] = benchmark::Counter(samples, benchmark::Counter::kIsRate);
  state.counters["rays/s"] = benchmark::Counter(rays, benchmark::Counter::kIsRate);
  state.counters["rays/sample"] = rays / samples;
}

}  // namespace

BENCHMARK_CAPTURE(BM_PathTracer, whitted, std::string("whitted.json"))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_PathTracer, cornell, std::string("cornell.json"))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
