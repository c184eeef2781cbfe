// Measurement tool for docs/benchmarks.md and docs/geometry.md (DISABLED_: run by hand with
// --gtest_also_run_disabled_tests --gtest_filter='GeometryFigures.*'): closest-hit rays per
// second on one sphere, tessellated at several levels and analytic (Embree user geometry), with
// the silhouette error of each tessellation; the cost per ray of sphere tracing; and the Whitted
// image of whitted.json with its spheres tessellated at several levels against the analytic one.
// Method: 640 x 480 pixel-centre primary rays of a camera framing the sphere, closest hit,
// single-ray queries on one thread (RtScene::intersect), the median of 5 runs after one warm-up.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <vector>

#include "engine/graph/recipe.h"
#include "engine/metrics/metrics.h"
#include "engine/rt/rt_scene.h"
#include "engine/scene/primitives.h"
#include "engine/scene/sdf.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

using namespace diptych;

namespace {

constexpr int kW = 640, kH = 480;

struct Timing {
  double raysPerSecond = 0;
  long hits = 0;
};

Timing timeRays(const RtScene& rt, const Camera& camera) {
  std::vector<double> rates;
  long hits = 0;
  for (int run = 0; run < 6; ++run) {
    hits = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        hits += rt.intersect(primaryRay(camera, kW, kH, x + 0.5f, y + 0.5f), 0.f,
                             std::numeric_limits<float>::infinity())
                    .has_value();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (run > 0) rates.push_back(double(kW) * kH / s);
  }
  std::sort(rates.begin(), rates.end());
  return {rates[rates.size() / 2], hits};
}

Camera framing() {
  Camera c;
  c.position = vec3(0.f, 0.f, 3.5f);
  c.target = vec3(0.f);
  c.verticalFov = glm::radians(40.f);
  return c;
}

}  // namespace

TEST(GeometryFigures, DISABLED_RaysPerSecondAgainstTriangles) {
  const Camera camera = framing();
  RtDevice device;
  std::printf(
      "| sphere | triangles | BVH/user data | rays/s | hit pixels |\n|---|---|---|---|---|\n");
  for (int slices : {16, 64, 256, 1024, 0}) {
    Scene scene;
    Mesh mesh = makeUvSphere(1.f, std::max(slices, 16), std::max(slices / 2, 8));
    if (slices == 0) mesh.analytic = AnalyticShape{ShapeType::Sphere, 1.f};
    scene.meshes.push_back(mesh);
    scene.instances.push_back({"sphere", 0, mat4(1.f)});
    const WorldGeometry world = flattenScene(scene);
    RtScene rt(device, world, scene);
    const Timing t = timeRays(rt, camera);
    const std::size_t triangles = slices == 0 ? 0 : world.triangleCount();
    // Input data Embree holds: 12 bytes per vertex and per triangle (its BVH comes on top);
    // the analytic sphere: one user primitive.
    const std::size_t bytes =
        slices == 0 ? sizeof(AnalyticInstance) : 12 * (mesh.positions.size() + triangles);
    std::printf("| %s | %zu | %zu B | %.3g | %ld |\n",
                slices == 0 ? "analytic"
                            : (std::to_string(slices) + " x " + std::to_string(slices / 2)).c_str(),
                triangles, bytes, t.raysPerSecond, t.hits);
  }
}

TEST(GeometryFigures, DISABLED_SphereTracingCostPerRay) {
  const Camera camera = framing();
  RtDevice device;
  std::printf(
      "| SDF | relaxation | rays/s | mean steps | max steps | capped "
      "|\n|---|---|---|---|---|---|\n");
  auto run = [&](const char* name, SdfNode node, double relaxation) {
    Scene scene;
    auto object = std::make_shared<SdfObject>();
    object->sdf.nodes.push_back(node);
    const auto b = sdfBounds(object->sdf);
    object->lo = b->first;
    object->hi = b->second;
    object->settings = {1e-5 * glm::length(b->second - b->first), 256, relaxation};
    Mesh mesh = polygonizeSdf(object->sdf, object->lo, object->hi, 16);
    mesh.sdf = object;
    scene.meshes.push_back(mesh);
    scene.instances.push_back({name, 0, mat4(1.f)});
    const WorldGeometry world = flattenScene(scene);
    RtScene rt(device, world, scene);
    rt.resetSdfStepStats();
    const Timing t = timeRays(rt, camera);
    const RtScene::SdfStepStats s = rt.sdfStepStats();
    std::printf("| %s | %.1f | %.3g | %.1f | %d | %llu |\n", name, relaxation, t.raysPerSecond,
                s.meanSteps(), s.maxSteps, (unsigned long long)s.capped);
  };
  SdfNode sphere;
  sphere.kind = SdfKind::Sphere;
  sphere.radius = 1.0;
  SdfNode sponge;
  sponge.kind = SdfKind::Menger;
  sponge.halfSize = dvec3(0.8);
  sponge.iterations = 4;
  for (double omega : {1.0, 1.6}) {
    run("sphere", sphere, omega);
    run("menger (4 levels)", sponge, omega);
  }
}

// whitted.json rendered by rt_whitted (640 x 480) with both spheres tessellated at slices x
// slices/2, against the same render with analytic spheres: relative RMSE, mean FLIP (LDR, 67
// pixels per degree, after clamping to [0, 1]), triangles and the frame's median time.
TEST(GeometryFigures, DISABLED_WhittedErrorAgainstTessellation) {
  const int w = 640, h = 480;
  const auto file = std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes" / "whitted.json";
  const Recipe recipe =
      loadRecipe(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "graphs" / "whitted.json");
  auto render = [&](int slices, double& ms, std::size_t& triangles) {
    Scene scene = loadScene(file);
    triangles = 0;
    for (Mesh& m : scene.meshes) {
      if (m.analytic && slices > 0) {
        const std::string name = m.name;
        const int material = m.material;
        m = makeUvSphere(m.analytic->radius, slices, slices / 2);
        m.name = name;
        m.material = material;
      }
      if (!m.analytic) triangles += m.triangleCount();
    }
    const auto t0 = std::chrono::steady_clock::now();
    auto frame =
        diptych::testing::renderHybridFrame(std::move(scene), w, h, {"reference.color"}, recipe);
    ms = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    Image img = frame->output("reference.color").toImage();
    return img;
  };
  double msExact;
  std::size_t trianglesExact;
  const Image exact = render(0, msExact, trianglesExact);
  auto clamp01 = [](Image img) {
    for (float& v : img.pixels) v = std::clamp(v, 0.f, 1.f);
    return img;
  };
  std::printf(
      "| spheres | triangles (scene) | sqrt(relMSE) | mean FLIP | frame ms "
      "|\n|---|---|---|---|---|\n");
  std::printf("| analytic | %zu | 0 | 0 | %.0f |\n", trianglesExact, msExact);
  for (int slices : {16, 32, 64, 128, 256}) {
    double ms;
    std::size_t triangles;
    const Image img = render(slices, ms, triangles);
    const double rmse = std::sqrt(relativeMeanSquaredError(img, exact, 1e-2));
    const FlipResult flip = ldrFlip(clamp01(img), clamp01(exact), 67.0);
    double mean = 0;
    for (float v : flip.map.pixels) mean += v;
    mean /= double(flip.map.pixels.size());
    std::printf("| %d x %d | %zu | %.3g | %.4f | %.0f |\n", slices, slices / 2, triangles, rmse,
                mean, ms);
  }
}
