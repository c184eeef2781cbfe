// The visibility G-buffer on an alpha-masked scene (the shared AlphaBlendModeTest.glb): the
// alpha-tested meshes keep the per-fragment (u, v) their test needs (docs/gl.md, GBufferTargets
// in engine/gl/gbuffer_raster.h), the opaque ones leave them NaN for the CPU to compute, and the
// CPU shade image is that of the exact variant: bit for bit on alpha-tested pixels, within the
// float intersection's rounding of (u, v) elsewhere.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "engine/gl/shading_buffers.h"
#include "passes/common/hits_texel.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/lit_model.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

Scene alphaScene() {
  Scene scene = loadScene(std::filesystem::path(DIPTYCH_SHARED_SCENES) /
                          "alpha-blend-mode-test/AlphaBlendModeTest.glb");
  // The file has no lights: the one test_alpha_mask_gltf.cpp adds, so the image is not black.
  testing::addTestLight(scene);
  return scene;
}

TEST(VisibilityAlpha, AlphaTestedMeshesKeepTheirBarycentrics) {
  const std::filesystem::path file =
      std::filesystem::path(DIPTYCH_SHARED_SCENES) / "alpha-blend-mode-test/AlphaBlendModeTest.glb";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not present";
  constexpr int w = 200, h = 150;
  auto visibility = testing::renderHybridFrame(alphaScene(), w, h, {"shade.color", "gbuffer.hits"});
  auto exact = testing::renderHybridFrame(alphaScene(), w, h, {},
                                          testing::withShadeInBothDomains(defaultHybridRecipe()));
  ASSERT_EQ(visibility->pass("gbuffer")->variant.rfind("visibility", 0), 0u)
      << visibility->pass("gbuffer")->variant;
  ASSERT_EQ(exact->pass("gbuffer")->variant.rfind("exact hits", 0), 0u);

  const CpuImage& hits = visibility->output("gbuffer.hits");
  const WorldGeometry& geometry = visibility->world->geometry();
  int tested = 0, opaque = 0, testedNaN = 0, opaqueComputed = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto hit = hitsTexel(hits, x, y);
      if (!hit) continue;
      const int material = geometry.meshes.at(std::size_t(hit->instance)).material;
      const bool nan = std::isnan(hit->u) || std::isnan(hit->v);
      if (gl::alphaDraw(visibility->scene, material) == gl::AlphaDraw::AlphaTested) {
        ++tested;
        testedNaN += nan;
      } else {
        ++opaque;
        opaqueComputed += !nan;
      }
    }
  std::printf("alpha-tested texels %d, opaque texels %d\n", tested, opaque);
  EXPECT_GT(tested, 100);
  EXPECT_GT(opaque, 100);
  EXPECT_EQ(testedNaN, 0);
  EXPECT_EQ(opaqueComputed, 0);

  // Opaque texels: the same triangle, (u, v) from GL (exact variant) or the C++ twin along the
  // same pixel ray (visibility variant). Both are float ray-triangle intersections, so they
  // agree to the float conditioning of the intersection (HybridConsistency's bound, relative to
  // the triangle's vertex scale), not to the last bit: measured max |du|, |dv| 8.2e-6 here, on
  // this scene's large box faces. Alpha-tested texels use GL's (u, v) in both: bit for bit.
  const CpuImage& exactHitsImage = exact->output("gbuffer.hits");
  const PinholeFrame pinhole(visibility->graph.frame.camera, w, h);
  const CpuImage& a = visibility->output("shade.color");
  const CpuImage& b = exact->output("shade_cpu.color");
  double num = 0, den = 0, worstUv = 0, worstTested = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double px = 0;
      for (int c = 0; c < 3; ++c) {
        const double d = double(a.f(x, y, c)) - double(b.f(x, y, c));
        num += d * d;
        den += double(b.f(x, y, c)) * double(b.f(x, y, c));
        px = std::max(px, std::abs(d));
      }
      const auto mine = triangleTexel(hits, geometry, pinhole, x, y);
      const auto gl = hitsTexel(exactHitsImage, x, y);
      ASSERT_EQ(bool(mine), bool(gl)) << x << "," << y;
      if (!mine) continue;
      ASSERT_EQ(mine->instance, gl->instance);
      ASSERT_EQ(mine->primitive, gl->primitive);
      const int material = geometry.meshes.at(std::size_t(mine->instance)).material;
      if (gl::alphaDraw(visibility->scene, material) == gl::AlphaDraw::AlphaTested)
        worstTested = std::max(worstTested, px);
      worstUv =
          std::max({worstUv, double(std::abs(mine->u - gl->u)), double(std::abs(mine->v - gl->v))});
    }
  ASSERT_GT(den, 0.0);
  const double e = std::sqrt(num / den);
  std::printf("max |(u, v) C++ - GL| %.3g; CPU shade relative RMSE %.3g; alpha-tested max %.3g\n",
              worstUv, e, worstTested);
  EXPECT_LT(worstUv, 2e-5);
  EXPECT_EQ(worstTested, 0.0);
  // The box labels' high-contrast texels turn that uv difference into up to 7e-3 on a few
  // pixels: measured relative RMSE 1.9e-4 (cf. 7.6e-6 on textures.json, VisibilityGBuffer).
  EXPECT_LT(e, 1e-3);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
