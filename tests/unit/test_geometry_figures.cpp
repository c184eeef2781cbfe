// Measurement tool for docs/benchmarks.md and docs/geometry.md (DISABLED_: run by hand with
// --gtest_also_run_disabled_tests --gtest_filter='GeometryFigures.*'): the Whitted image of
// whitted.json with its spheres tessellated at several levels against the analytic one. Rays
// per second against triangles and sphere-tracing cost per ray are google-benchmarks:
// tests/bench/bench_geometry.cpp.
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
#include "engine/scene/primitives.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

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

}  // namespace DIPTYCH_UNITY_ID
