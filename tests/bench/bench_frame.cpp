// One frame of the default hybrid graph end to end (gbuffer on OSMesa/llvmpipe -> readback ->
// rt_shadows on Embree + TBB -> shade on the CPU), per sample scene and image size.
//
// Method: the graph is compiled, the context, world and executor are created once per
// benchmark, kWarmupFrames frames are run and their timings dropped (this builds the Embree
// BVH, uploads the GL buffers and compiles the shaders), then every benchmark iteration is one
// GraphExecutor::runFrame(). The benchmark's own time is the whole frame (wall clock). The
// counters are medians over the measured iterations of GraphExecutor::timings():
//   ms:NODE      CPU wall time (steady_clock) of each schedule node
//   gpu_ms:NODE  GL_TIME_ELAPSED of GL nodes and transfers (see docs/benchmarks.md before
//                trusting these on llvmpipe)
//   rays         shadow rays traced per frame by rt_shadows
//   rays/s       rays / median rt_shadows CPU time (the whole pass: receiver setup, ray
//                generation, Embree traversal and write-back)
// BM_ShadowsBreakdown splits the rt_shadows pass of the same frame into its three phases
// (receiver setup from the read-back G-buffer, traceShadowRays, visibility write-back) by
// repeating them here on the frame's real G-buffer; the code mirrors passes/rt/rt_shadows.cpp.
// The timings are wall clock on a shared machine: they are reported, never asserted.
#include <benchmark/benchmark.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/timing.h"
#include "engine/gl/context.h"
#include "engine/graph/executor.h"
#include "engine/graph/render_world.h"
#include "engine/rt/ray_offset.h"
#include "engine/rt/shadow_rays.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/load.h"
#include "passes/common/hits_texel.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

using namespace diptych;

namespace {

constexpr int kWarmupFrames = 3;
constexpr int kMeasuredFrames = 10;

Scene loadSample(const std::string& name) {
  return loadScene(std::string(DIPTYCH_SAMPLES_DIR) + "/scenes/" + name);
}

// The compiled hybrid frame with its context, world and executor, warmed up.
struct HybridFrame {
  CompiledGraph graph;
  std::unique_ptr<gl::GlContext> context;
  std::unique_ptr<RenderWorld> world;
  std::unique_ptr<GraphExecutor> executor;

  HybridFrame(const Scene& scene, int width, int height,
              const std::vector<std::string>& outputs = {}) {
    const FrameSettings frame{
        .width = width,
        .height = height,
        .camera = scene.hasCamera ? scene.camera : frameBounds(scene.bounds())};
    graph = compileGraph(defaultHybridRecipe(), builtinPasses(), scene, frame, outputs);
    if (graph.usesGl()) context = gl::createContext(gl::ContextKind::Osmesa, width, height);
    world = std::make_unique<RenderWorld>(scene, context.get());
    executor = std::make_unique<GraphExecutor>(graph, *world);
    for (int f = 0; f < kWarmupFrames; ++f) executor->runFrame();
    executor->clearTimings();
  }
  // Members are destroyed in reverse order: the executor and the world (which own GL objects)
  // go before the context, the graph (which the executor refers to) last.
  HybridFrame(const HybridFrame&) = delete;
  HybridFrame& operator=(const HybridFrame&) = delete;
};

void BM_HybridFrame(benchmark::State& state, const std::string& sceneName) {
  const Scene scene = loadSample(sceneName);
  HybridFrame h(scene, int(state.range(0)), int(state.range(1)));
  const CompiledGraph& graph = h.graph;
  GraphExecutor& executor = *h.executor;

  for (auto _ : state) executor.runFrame();

  const std::vector<NodeTiming>& timings = executor.timings();
  double totalMs = 0;
  for (std::size_t n = 0; n < graph.nodes.size(); ++n) {
    const NodeTiming& t = timings[n];
    const double cpu = summarize(t.cpuMs).median;
    totalMs += cpu;
    state.counters["ms:" + graph.nodes[n].name] = cpu;
    if (!t.gpuMs.empty())
      state.counters["gpu_ms:" + graph.nodes[n].name] = summarize(t.gpuMs).median;
    if (auto it = t.counters.find("rays"); it != t.counters.end()) {
      state.counters["rays"] = it->second;
      if (cpu > 0) state.counters["rays/s"] = it->second / (cpu * 1e-3);
    }
  }
  state.counters["ms:total"] = totalMs;  // sum of per-node medians
  state.counters["triangles"] = double(h.world->geometry().triangleCount());
}

void BM_ShadowsBreakdown(benchmark::State& state, const std::string& sceneName) {
  const Scene scene = loadSample(sceneName);
  HybridFrame h(scene, int(state.range(0)), int(state.range(1)), {"shade.color", "gbuffer.hits"});
  const CpuImage& gbuffer = h.executor->output("gbuffer.hits");
  RenderWorld& world = *h.world;
  const auto& lights = world.scene().lights;
  const RtScene& rt = world.rtScene();
  const int w = gbuffer.desc.width, hgt = gbuffer.desc.height;
  const int layers = std::max<int>(1, int(lights.size()));
  CpuImage out(ResourceDesc{Format::R32F, w, hgt, layers});

  std::vector<double> setupMs, traceMs, writeMs;
  std::size_t rays = 0;
  const PinholeFrame pinhole(h.graph.frame.camera, w, hgt);
  for (auto _ : state) {
    Stopwatch clock;
    std::vector<int> pixelOf;
    std::vector<ShadowReceiver> receivers;
    pixelOf.reserve(std::size_t(w) * hgt);
    receivers.reserve(std::size_t(w) * hgt);
    for (int y = 0; y < hgt; ++y) {
      for (int x = 0; x < w; ++x) {
        // The hybrid's G-buffer is a visibility buffer: (u, v) from the pixel ray.
        const auto hit = triangleTexel(gbuffer, world.geometry(), pinhole, x, y);
        if (!hit) continue;
        const WorldMesh& mesh = world.geometry().meshes.at(hit->instance);
        const std::uint32_t* tri = &mesh.indices.at(3 * std::size_t(hit->primitive));
        receivers.push_back({interpolatePosition(mesh, hit->primitive, hit->u, hit->v),
                             geometricNormal(mesh, hit->primitive),
                             vertexMagnitude(mesh.positions[tri[0]], mesh.positions[tri[1]],
                                             mesh.positions[tri[2]])});
        pixelOf.push_back(y * w + x);
      }
    }
    setupMs.push_back(clock.milliseconds());
    clock.restart();
    const std::vector<float> visibility = traceShadowRays(rt, lights, receivers);
    traceMs.push_back(clock.milliseconds());
    clock.restart();
    out.fill(vec4(1.f));
    const std::size_t n = receivers.size();
    tbb::parallel_for(std::size_t(0), lights.size(), [&](std::size_t l) {
      for (std::size_t i = 0; i < n; ++i)
        out.setF(pixelOf[i] % w, pixelOf[i] / w, 0, visibility[l * n + i], int(l));
    });
    writeMs.push_back(clock.milliseconds());
    rays = 0;
    for (const Light& light : lights) rays += light.castsShadows ? n : 0;
    benchmark::DoNotOptimize(out.words.data());
  }
  const double setup = summarize(setupMs).median, trace = summarize(traceMs).median,
               write = summarize(writeMs).median;
  state.counters["ms:setup"] = setup;
  state.counters["ms:trace"] = trace;
  state.counters["ms:write"] = write;
  state.counters["rays"] = double(rays);
  if (trace > 0) state.counters["trace_rays/s"] = double(rays) / (trace * 1e-3);
  if (setup + trace + write > 0)
    state.counters["pass_rays/s"] = double(rays) / ((setup + trace + write) * 1e-3);
}

void sizes(benchmark::internal::Benchmark* b) {
  b->Args({640, 480})->Args({1920, 1080});
  b->ArgNames({"w", "h"});
  b->Iterations(kMeasuredFrames);
  b->Unit(benchmark::kMillisecond);
  b->UseRealTime();
}

}  // namespace

BENCHMARK_CAPTURE(BM_HybridFrame, whitted, std::string("whitted.json"))->Apply(sizes);
BENCHMARK_CAPTURE(BM_HybridFrame, cornell, std::string("cornell.json"))->Apply(sizes);
BENCHMARK_CAPTURE(BM_ShadowsBreakdown, whitted, std::string("whitted.json"))->Apply(sizes);
BENCHMARK_CAPTURE(BM_ShadowsBreakdown, cornell, std::string("cornell.json"))->Apply(sizes);
