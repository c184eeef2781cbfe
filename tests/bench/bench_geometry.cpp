// Geometry cost per ray (docs/benchmarks-history.md, "Geometry"): closest-hit rays per second on
// one unit sphere tessellated at several levels against the same sphere as Embree user geometry
// (analytic), and the cost per ray of sphere tracing, plain (Hart 1996) against over-relaxed
// (Keinert et al. 2014), with the steps each ray took. Method: 640 x 480 pixel-centre primary
// rays of a camera framing the sphere, single-ray RtScene::intersect on one thread, Embree
// build quality medium, robust traversal. items_per_second = rays/s. Run:
//   diptych_benchmarks --benchmark_filter='Geometry' --benchmark_repetitions=3
#include <benchmark/benchmark.h>

#include <limits>
#include <memory>
#include <string>

#include "engine/rt/rt_scene.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/primitives.h"
#include "engine/scene/sdf.h"

using namespace diptych;

namespace {

constexpr int kW = 640, kH = 480;

Camera framing() {
  Camera c;
  c.position = vec3(0.f, 0.f, 3.5f);
  c.target = vec3(0.f);
  c.verticalFov = glm::radians(40.f);
  return c;
}

// Traces the frame's primary rays once per iteration; returns the hits of the last one.
long traceFrames(benchmark::State& state, const RtScene& rt) {
  const PinholeFrame pinhole(framing(), kW, kH);
  long hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        hits += rt.intersect(pinhole.ray(x + 0.5f, y + 0.5f), 0.f,
                             std::numeric_limits<float>::infinity())
                    .has_value();
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * kW * kH);
  return hits;
}

// Arg: slices of the uv sphere (stacks = slices / 2); 0 = the analytic sphere.
void BM_GeometrySphereRays(benchmark::State& state) {
  const int slices = int(state.range(0));
  Scene scene;
  Mesh mesh = makeUvSphere(1.f, slices > 0 ? slices : 16, slices > 0 ? slices / 2 : 8);
  if (slices == 0) mesh.analytic = AnalyticShape{ShapeType::Sphere, 1.f};
  scene.meshes.push_back(mesh);
  scene.instances.push_back({"sphere", 0, mat4(1.f)});
  const WorldGeometry world = flattenScene(scene);
  RtDevice device;
  const RtScene rt(device, world, scene);
  const long hits = traceFrames(state, rt);
  state.counters["triangles"] = slices > 0 ? double(world.triangleCount()) : 0.0;
  state.counters["hit_pixels"] = double(hits);
  state.SetLabel(slices > 0 ? std::to_string(slices) + "x" + std::to_string(slices / 2)
                            : "analytic");
}

// Args: shape (0 = SDF sphere of radius 1, 1 = Menger sponge of 4 levels, half size 0.8) and
// relaxation x 10 (10 = plain, 16 = over-relaxed). Tolerance 1e-5 of the box diagonal, cap 256.
void BM_GeometrySphereTracing(benchmark::State& state) {
  SdfNode node;
  if (state.range(0) == 0) {
    node.kind = SdfKind::Sphere;
    node.radius = 1.0;
  } else {
    node.kind = SdfKind::Menger;
    node.halfSize = dvec3(0.8);
    node.iterations = 4;
  }
  auto object = std::make_shared<SdfObject>();
  object->sdf.nodes.push_back(node);
  const auto box = sdfBounds(object->sdf);
  object->lo = box->first;
  object->hi = box->second;
  object->settings = {1e-5 * glm::length(box->second - box->first), 256,
                      double(state.range(1)) / 10.0};
  Scene scene;
  Mesh mesh = polygonizeSdf(object->sdf, object->lo, object->hi, 16);
  mesh.sdf = object;
  scene.meshes.push_back(mesh);
  scene.instances.push_back({"sdf", 0, mat4(1.f)});
  const WorldGeometry world = flattenScene(scene);
  RtDevice device;
  const RtScene rt(device, world, scene);
  rt.resetSdfStepStats();
  traceFrames(state, rt);
  const RtScene::SdfStepStats s = rt.sdfStepStats();
  state.counters["mean_steps"] = s.meanSteps();
  state.counters["max_steps"] = s.maxSteps;
  state.counters["capped_per_frame"] = double(s.capped) / double(state.iterations());
  state.SetLabel(std::string(state.range(0) == 0 ? "sphere" : "menger-4") + " relaxation " +
                 std::to_string(double(state.range(1)) / 10.0).substr(0, 3));
}

}  // namespace

BENCHMARK(BM_GeometrySphereRays)
    ->Arg(16)
    ->Arg(64)
    ->Arg(256)
    ->Arg(1024)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GeometrySphereTracing)
    ->Args({0, 10})
    ->Args({0, 16})
    ->Args({1, 10})
    ->Args({1, 16})
    ->Unit(benchmark::kMillisecond);
