// The texture_filtering slot on samples/scenes/textures.json (a checkerboard image on a plane
// receding to the horizon): each raster producer's albedo signal against the exact producer's
// (texture_supersample, 8 x 8 sub-pixel rays), over the ground's pixels, and ray-cone LOD at
// reflected hits against level 0. What the lecture and the filtering literature predict, measured
// as mean absolute error on the signal:
// - nearest and bilinear (level 0, no mipmaps) alias: larger error than trilinear;
// - anisotropic filtering is closest (trilinear blurs along the receding axis);
// - the lecture's distance-based level lies between (it ignores the slant);
// - ray cones bring the mirror's reflection of the far ground closer to a supersampled reflection
//   than level-0 lookups.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>

#include "passes/slots.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

const std::filesystem::path kScene =
    std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/textures.json";
constexpr int kW = 96, kH = 72;

CpuImage albedoOf(const std::string& producer) {
  Recipe r = defaultHybridRecipe();
  applySlotOverride(r, parseSlotOverride("texture_filtering=" + producer), builtinPasses());
  const auto f =
      testing::renderHybridFrame(loadScene(kScene), kW, kH, {"texture_filtering.albedo"}, r);
  return f->output("texture_filtering.albedo");
}

// Mean |a - b| over the RGB of pixels both producers filled (albedo >= 0) below the horizon row
// band where the ground recedes (the lower half of the frame holds the near ground only).
double meanError(const CpuImage& a, const CpuImage& b) {
  double sum = 0.0;
  int n = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      if (a.f(x, y, 3) < 0.f || b.f(x, y, 3) < 0.f) continue;
      for (int c = 0; c < 3; ++c) sum += std::fabs(double(a.f(x, y, c)) - b.f(x, y, c));
      ++n;
    }
  return n ? sum / (3.0 * n) : 0.0;
}

TEST(TextureFiltering, MipmapsAndAnisotropyBeatLevelZeroAgainstSupersampling) {
  const CpuImage exact = albedoOf("texture_supersample:samples=8");
  std::map<std::string, double> error;
  for (const char* p : {"texture_nearest", "texture_bilinear", "texture_distance",
                        "texture_trilinear", "texture_anisotropic"})
    error[p] = meanError(albedoOf(p), exact);
  for (const auto& [p, e] : error)
    std::cout << p << ": mean |albedo - supersampled| = " << e << "\n";
  EXPECT_GT(error["texture_nearest"], error["texture_trilinear"]);
  EXPECT_GT(error["texture_bilinear"], error["texture_trilinear"]);
  EXPECT_LT(error["texture_anisotropic"], error["texture_trilinear"]);
  EXPECT_LT(error["texture_anisotropic"], error["texture_distance"]);
}

TEST(TextureFiltering, SupersampleWithOneSampleIsThePixelCentreLookup) {
  // N = 1 (the built-in recipe's setting) is the reference's own level-0 lookup at the centre:
  // equal to bilinear on level 0 (the ground texture's magnification filter) wherever the
  // centre ray and the G-buffer agree on the triangle.
  const CpuImage one = albedoOf("texture_supersample:samples=1");
  const CpuImage bilinear = albedoOf("texture_bilinear");
  EXPECT_LT(meanError(one, bilinear), 1e-4);
}

CpuImage colorOf(Recipe r) {
  const auto f = testing::renderHybridFrame(loadScene(kScene), kW, kH, {"shade.color"}, r);
  return f->output("shade.color");
}

// shade takes C from its albedo input: a different filter changes the frame, and the built-in
// recipe's N = 1 signal gives the frame shade makes with its own lookup (input removed).
TEST(TextureFiltering, ShadeUsesTheAlbedoInput) {
  Recipe nearest = defaultHybridRecipe(), own = defaultHybridRecipe();
  applySlotOverride(nearest, parseSlotOverride("texture_filtering=texture_nearest"),
                    builtinPasses());
  for (RecipePass& p : own.passes)
    if (p.type == "shade") p.inputs.erase("albedo");
  const CpuImage builtIn = colorOf(defaultHybridRecipe());
  const CpuImage withoutAlbedo = colorOf(own);
  const CpuImage withNearest = colorOf(nearest);
  double same = 0.0, changed = 0.0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (int c = 0; c < 3; ++c) {
        same += std::fabs(builtIn.f(x, y, c) - withoutAlbedo.f(x, y, c));
        changed += std::fabs(builtIn.f(x, y, c) - withNearest.f(x, y, c));
      }
  same /= 3.0 * kW * kH;
  changed /= 3.0 * kW * kH;
  std::cout << "mean |built-in - own lookup| = " << same << ", |built-in - nearest| = " << changed
            << "\n";
  EXPECT_LT(same, 1e-4);
  EXPECT_GT(changed, 10.0 * same + 1e-4);
}

CpuImage reflectionOf(const std::string& lod, int w, int h) {
  Recipe r = defaultHybridRecipe();
  applySlotOverride(r, parseSlotOverride("reflection=rt_reflection:texture_lod=" + lod),
                    builtinPasses());
  const auto f = testing::renderHybridFrame(loadScene(kScene), w, h, {"reflection.reflection"}, r);
  return f->output("reflection.reflection");
}

TEST(TextureFiltering, RayConesLowerTheErrorOfDistantReflections) {
  constexpr int kS = 6;  // reference: level 0 at kS x kS the resolution, box-averaged
  const CpuImage fine = reflectionOf("level0", kW * kS, kH * kS);
  const CpuImage level0 = reflectionOf("level0", kW, kH), cone = reflectionOf("cone", kW, kH);
  double e0 = 0.0, ec = 0.0;
  int n = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      if (level0.f(x, y, 0) == 0.f && level0.f(x, y, 1) == 0.f) continue;  // not the mirror
      for (int c = 0; c < 3; ++c) {
        double ref = 0.0;
        for (int j = 0; j < kS; ++j)
          for (int i = 0; i < kS; ++i) ref += fine.f(x * kS + i, y * kS + j, c);
        ref /= kS * kS;
        e0 += std::fabs(level0.f(x, y, c) - ref);
        ec += std::fabs(cone.f(x, y, c) - ref);
      }
      ++n;
    }
  ASSERT_GT(n, 50) << "the mirror covers too few pixels";
  std::cout << n << " mirror pixels: mean error level 0 " << e0 / (3 * n) << ", ray cones "
            << ec / (3 * n) << "\n";
  EXPECT_LT(ec, e0);
}

// The full ray tracers take the same ray cones (texture_lod=cone) for their own primary hits
// (RTG eq. 20.30: width 0 at the eye, the pixel's spread): each producer's one-sample frame
// comes closer to its own frame supersampled kS x kS (level 0, box-averaged) than with level 0.
// With spp > 1 each sample's cone spreads over its stratum, the pixel's spread / sqrt(spp).
// rt_path traces emission and direct light only (max_depth 1), so the frames differ only by
// texture lookups and the jittered pixel position.
CpuImage tracedOf(const std::string& type, nlohmann::json params, const std::string& lod, int w,
                  int h) {
  params["texture_lod"] = lod;
  Recipe r;
  r.passes = {{.name = "traced", .type = type, .params = params, .place = "test"}};
  r.outputs = {"traced.color"};
  return testing::renderHybridFrame(loadScene(kScene), w, h, {}, r)->output("traced.color");
}

TEST(TextureFiltering, RayConesInTheFullRayTracers) {
  constexpr int kS = 4;
  const std::pair<const char*, nlohmann::json> producers[] = {
      {"rt_whitted", nlohmann::json::object()},
      {"rt_distributed", {{"spp", 4}}},
      {"rt_path", {{"spp", 1}, {"max_depth", 1}}}};
  for (const auto& [type, params] : producers) {
    const CpuImage fine = tracedOf(type, params, "level0", kW * kS, kH * kS);
    const CpuImage level0 = tracedOf(type, params, "level0", kW, kH);
    const CpuImage cone = tracedOf(type, params, "cone", kW, kH);
    double e0 = 0.0, ec = 0.0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        for (int c = 0; c < 3; ++c) {
          double ref = 0.0;
          for (int j = 0; j < kS; ++j)
            for (int i = 0; i < kS; ++i) ref += fine.f(x * kS + i, y * kS + j, c);
          ref /= kS * kS;
          e0 += std::fabs(level0.f(x, y, c) - ref);
          ec += std::fabs(cone.f(x, y, c) - ref);
        }
    std::cout << type << ": mean error level 0 " << e0 / (3 * kW * kH) << ", ray cones "
              << ec / (3 * kW * kH) << "\n";
    EXPECT_LT(ec, e0) << type;
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
