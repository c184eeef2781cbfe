// Prefiltered environment lookups for rough glTF metals (passes/raster/env_prefilter.h): a white
// glTF metal sphere under a synthetic environment, no light. The exact answer is the path tracer
// (the GGX lobe integrated by importance sampling; on a convex metal every path is one bounce to
// the environment). The raster frame is gbuffer -> env_* -> shade, with `prefilter` on (the lobe's
// prefiltered radiance, weighted by the split-sum albedo) and off (one mirror lookup faded by
// 1 - roughness). Prefiltering must be closer to the path tracer for rough spheres, and change
// nothing at roughness 0.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/recipe.h"
#include "engine/graph/render_world.h"
#include "engine/rt/path_tracer.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/raster/env_prefilter.h"
#include "passes/registry.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

namespace fs = std::filesystem;
constexpr int kSize = 64;
constexpr int kSpp = 64;

// Structured but smooth: a warm lobe toward +x, a cool sky toward +y, a dim floor. Blurring it
// by a rough lobe changes it visibly; the path tracer converges on it quickly.
vec3 environmentAt(vec3 d) {
  const float warm = std::pow(std::max(0.f, d.x), 4.f), sky = std::max(0.f, d.y);
  return vec3(0.15f) + 2.5f * warm * vec3(1.f, 0.8f, 0.5f) + sky * vec3(0.3f, 0.5f, 1.f);
}

class EnvPrefilter : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("diptych_prefilter_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    Image img(512, 256, 3);
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const float phi = ((x + 0.5f) / img.width - 0.5f) * 2.f * glm::pi<float>();
        const float theta = (y + 0.5f) / img.height * glm::pi<float>();
        const vec3 c = environmentAt(vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                          std::sin(theta) * std::sin(phi)));
        for (int k = 0; k < 3; ++k) img.at(x, y, k) = c[k];
      }
    writeImage(dir_ / "env.exr", img);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static Scene metalSphere(float roughness) {
    const nlohmann::json scene = {
        {"camera", {{"position", {0.4, 0.5, 3.2}}, {"target", {0, 0, 0}}, {"fov", 45}}},
        {"environment", {{"equirect", "env.exr"}}},
        {"materials",
         {{"metal",
           {{"model", "gltf"},
            {"base_color", {1, 1, 1}},
            {"metallic", 1},
            {"roughness", roughness}}}}},
        {"objects",
         {{{"type", "sphere"}, {"radius", 1}, {"segments", {192, 96}}, {"material", "metal"}}}}};
    const fs::path path = dir_ / ("sphere" + std::to_string(int(roughness * 100)) + ".json");
    std::ofstream(path) << scene.dump(1);
    return loadScene(path);
  }
  static fs::path dir_;
};
fs::path EnvPrefilter::dir_;

// gbuffer -> env producer -> CPU shade; the shaded colour and the hits texel.
struct RasterFrame {
  CpuImage color, hits;
};
RasterFrame raster(const Scene& scene, const std::string& producer, bool prefilter) {
  const nlohmann::json recipe = {
      {"passes",
       {{{"name", "gbuffer"}, {"type", "gbuffer"}},
        {{"name", "env"},
         {"type", producer},
         {"params", {{"prefilter", prefilter}}},
         {"inputs", {{"hits", "gbuffer.hits"}}}},
        {{"name", "shade"},
         {"type", "shade"},
         {"params", {{"domain", "cpu"}}},
         {"inputs", {{"hits", "gbuffer.hits"}, {"reflection", "env.reflection"}}}}}},
      {"outputs", {"shade.color", "gbuffer.hits"}}};
  const FrameSettings frame{.width = kSize, .height = kSize, .camera = scene.camera};
  const CompiledGraph graph =
      compileGraph(parseRecipe(recipe, "test"), builtinPasses(), scene, frame);
  RenderWorld world(scene, &gl::testing::osmesaContext());
  GraphExecutor executor(graph, world);
  executor.runFrame();
  return {executor.output("shade.color"), executor.output("gbuffer.hits")};
}

// Path-traced radiance per pixel (spp paths), the exact answer.
std::vector<vec3> pathTraced(const Scene& scene, int spp) {
  RenderWorld world(scene);
  const PathTracer tracer(scene, world.geometry(), world.rtScene(), {8, 8, false});
  std::vector<vec3> out(std::size_t(kSize) * kSize, vec3(0.f));
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const Ray ray = primaryRay(scene.camera, kSize, kSize, x + 0.5f, y + 0.5f);
      vec3 sum(0.f);
      for (int s = 0; s < spp; ++s) {
        PathRng rng(std::uint32_t(y * kSize + x), std::uint32_t(s), 11u);
        sum += tracer.radiance(ray, rng).radiance;
      }
      out[std::size_t(y) * kSize + x] = sum / float(spp);
    }
  return out;
}

// Over the sphere's pixels (hits texel set), all three channels: RMSE and mean signed error.
struct SphereError {
  double rmse = 0, bias = 0;
};
SphereError sphereError(const RasterFrame& f, const std::vector<vec3>& exact) {
  double sum = 0, signedSum = 0;
  int n = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (f.hits.u(x, y, 0) == 0u) continue;
      for (int k = 0; k < 3; ++k) {
        const double d = f.color.f(x, y, k) - exact[std::size_t(y) * kSize + x][k];
        sum += d * d;
        signedSum += d;
        ++n;
      }
    }
  EXPECT_GT(n, 3 * 1000);
  return {std::sqrt(sum / std::max(n, 1)), signedSum / std::max(n, 1)};
}

TEST(EnvPrefilterLevels, CountAndRoughnessSteps) {
  EXPECT_EQ(envmap::prefilterLevelCount(256, 256), 6);  // 256 .. 8: roughness 0, 0.2, .., 1
  EXPECT_EQ(envmap::prefilterLevelCount(1024, 512), 6);
  EXPECT_EQ(envmap::prefilterLevelCount(16, 16), 3);  // 16, 8, 4
  EXPECT_EQ(envmap::prefilterLevelCount(1, 1), 1);
}

// A constant environment prefilters to itself at any roughness (the lobe average of a constant).
TEST(EnvPrefilterLevels, ConstantEnvironmentIsAFixedPoint) {
  Environment env;
  env.type = EnvironmentType::Color;
  env.color = vec3(0.25f, 0.5f, 1.f);
  const envmap::CubeChain source(env, 16);
  for (float roughness : {0.2f, 1.f}) {
    const Image level = envmap::prefilteredLevel(source, 8, 4, roughness, [](vec2 st) {
      return vec3(std::cos(6.f * st.x), st.y - 0.5f, std::sin(6.f * st.x));
    });
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 8; ++x)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(level.at(x, y, k), env.color[k], 1e-5f);
  }
}

TEST_F(EnvPrefilter, RoughMetalIsCloserToThePathTracerWithPrefiltering) {
  for (const char* producer : {"env_equirect", "env_cube"})
    for (float roughness : {0.4f, 0.8f}) {
      const Scene scene = metalSphere(roughness);
      const std::vector<vec3> exact = pathTraced(scene, kSpp);
      const SphereError with = sphereError(raster(scene, producer, true), exact);
      const SphereError without = sphereError(raster(scene, producer, false), exact);
      std::printf(
          "[ measured ] %s roughness %.1f vs path tracer (%d spp): prefiltered RMSE %.4f "
          "mean error %+.4f; mirror faded by roughness RMSE %.4f mean error %+.4f\n",
          producer, roughness, kSpp, with.rmse, with.bias, without.rmse, without.bias);
      EXPECT_LT(with.rmse, 0.5 * without.rmse) << producer << " roughness " << roughness;
    }
}

TEST_F(EnvPrefilter, RoughnessZeroIsUnchanged) {
  const Scene scene = metalSphere(0.f);
  for (const char* producer : {"env_equirect", "env_cube", "env_sphere"}) {
    const RasterFrame with = raster(scene, producer, true),
                      without = raster(scene, producer, false);
    float worst = 0.f;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        for (int k = 0; k < 3; ++k)
          worst = std::max(worst, std::abs(with.color.f(x, y, k) - without.color.f(x, y, k)));
    EXPECT_EQ(worst, 0.f) << producer;
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
