// KHR_materials_volume attenuation (shading.glsl volumeTransmittance, docs/materials.md): a glass
// sphere of radius 1 (the lecture's model: k_t = 1, no mirror term, ior 1 so that rays go
// straight) under a white sky, no light, attenuation colour c reached after distance d_a = 1.
// The pixel ray through the centre crosses 2 units of glass, so Beer-Lambert predicts exactly
// c^2 on the exact side (Whitted, the path tracer) and, with thicknessFactor 2, on the raster
// side (sorted_blend's transmission signal) too. Without the extension both give 1.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/recipe.h"
#include "engine/graph/render_world.h"
#include "engine/rt/path_tracer.h"
#include "engine/rt/whitted.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/load.h"
#include "engine/shading/shading.h"
#include "gl_test_context.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kSize = 33;  // odd: the centre pixel's ray passes through the sphere's centre
const vec3 kColor(0.5f, 0.7f, 0.9f);

Scene glassSphere(bool volume) {
  nlohmann::json glass = {{"kd", 0}, {"kt", 1}, {"transmit_color", {1, 1, 1}}, {"ior", 1.0}};
  if (volume) {
    glass["thickness"] = 2.0;
    glass["attenuation_color"] = {kColor.x, kColor.y, kColor.z};
    glass["attenuation_distance"] = 1.0;
  }
  const nlohmann::json scene = {
      {"camera", {{"position", {0, 0, 4}}, {"target", {0, 0, 0}}, {"fov", 40}}},
      {"environment", {{"color", {1, 1, 1}}}},
      {"materials", {{"glass", glass}}},
      {"objects",
       {{{"type", "sphere"}, {"radius", 1}, {"segments", {256, 128}}, {"material", "glass"}}}}};
  const auto dir = testing::scratchDir("volume");
  const auto path = dir / (volume ? "volume.json" : "thin.json");
  std::ofstream(path) << scene.dump();
  return loadScene(path);
}

Ray centreRay(const Scene& s) {
  return primaryRay(s.camera, kSize, kSize, kSize / 2 + 0.5f, kSize / 2 + 0.5f);
}

vec3 whitted(const Scene& s) {
  RenderWorld world(s);
  const WhittedTracer tracer(s, world.geometry(), world.rtScene(), WhittedSettings{});
  return tracer.radiance(centreRay(s), 1, 0u);
}

vec3 pathTraced(const Scene& s) {
  RenderWorld world(s);
  const PathTracer tracer(s, world.geometry(), world.rtScene(), {8, 8, false});
  PathRng rng(0u, 0u, 1u);  // one lobe (transmission) at every hit: a deterministic path
  return tracer.radiance(centreRay(s), rng).radiance;
}

vec3 sortedBlendSignal(const Scene& s) {
  const nlohmann::json recipe = {
      {"passes",
       {{{"name", "gbuffer"}, {"type", "gbuffer"}},
        {{"name", "blend"}, {"type", "sorted_blend"}, {"inputs", {{"hits", "gbuffer.hits"}}}}}},
      {"outputs", {"blend.transmission"}}};
  const FrameSettings frame{.width = kSize, .height = kSize, .camera = s.camera};
  const CompiledGraph graph = compileGraph(parseRecipe(recipe, "test"), builtinPasses(), s, frame);
  RenderWorld world(s, &gl::testing::osmesaContext());
  GraphExecutor executor(graph, world);
  executor.runFrame();
  const CpuImage& t = executor.output("blend.transmission");
  return vec3(t.f(kSize / 2, kSize / 2, 0), t.f(kSize / 2, kSize / 2, 1),
              t.f(kSize / 2, kSize / 2, 2));
}

void expectNear(vec3 got, vec3 want, float tolerance, const char* what) {
  std::printf("[ measured ] %s: (%.5f, %.5f, %.5f), predicted (%.5f, %.5f, %.5f)\n", what, got.x,
              got.y, got.z, want.x, want.y, want.z);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], tolerance * want[k]) << what << " " << k;
}

TEST(VolumeAttenuation, TransmittanceIsBeerLambert) {
  const vec3 t = shading::volumeTransmittance(kColor, 1.f, 2.f);
  EXPECT_FLOAT_EQ(t.x, 0.25f);
  EXPECT_FLOAT_EQ(t.y, std::exp(-2.f * -std::log(0.7f)));
  EXPECT_EQ(shading::volumeTransmittance(kColor, 0.f, 2.f), vec3(1.f));  // no attenuation distance
  EXPECT_EQ(shading::volumeTransmittance(kColor, 1.f, 0.f), vec3(1.f));
  EXPECT_EQ(shading::volumeTransmittance(vec3(0.f), 1.f, 1.f), vec3(0.f));
}

// The tessellated sphere's chord through the centre is 2 cos(pi / 256) ~ 2 (1 - 7.5e-5): 1e-3.
TEST(VolumeAttenuation, ExactSidesDarkenARayThroughTheCentreByTheBeerLambertFactor) {
  const vec3 predicted = shading::volumeTransmittance(kColor, 1.f, 2.f);
  expectNear(whitted(glassSphere(false)), vec3(1.f), 1e-4f, "whitted, thin-walled");
  expectNear(whitted(glassSphere(true)), predicted, 1e-3f, "whitted, volume");
  expectNear(pathTraced(glassSphere(true)), predicted, 1e-3f, "path tracer, volume");
}

TEST(VolumeAttenuation, RasterBlendAppliesTheThicknessOnce) {
  const vec3 predicted = shading::volumeTransmittance(kColor, 1.f, 2.f);
  const vec3 thin = sortedBlendSignal(glassSphere(false));
  expectNear(thin, vec3(1.f), 1e-4f, "sorted_blend, thin-walled");
  expectNear(sortedBlendSignal(glassSphere(true)), predicted * thin, 1e-4f, "sorted_blend, volume");
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
