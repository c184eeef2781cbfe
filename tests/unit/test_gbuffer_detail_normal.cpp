// The G-buffer's own normal output carries the surface detail (shaders/gbuffer.frag,
// DIPTYCH_DETAIL_NORMAL): on samples/scenes/surface-detail.json (sphere tessellated: GL draws
// triangles), with the lecture's bump map and with the normal map baked from it, gbuffer.normal
// must be the shading normal the CPU computes for the same hits texel (makeSurfacePoint, the
// normal every CPU pass shades with), and must differ from the interpolated vertex normal
// (otherwise the comparison would not show anything).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "engine/graph/recipe.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/primitives.h"
#include "engine/shading/surface_detail.h"
#include "passes/common/hits_texel.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

namespace fs = std::filesystem;

struct Angles {
  double parityP99 = 0, parityMax = 0;  // GL normal vs CPU shading normal (rad)
  double detailShare = 0;  // share of pixels whose normal is > 0.02 rad off the vertex normal
  int pixels = 0;
};

Angles measure(const Scene& scene, const Scene& flat) {
  const nlohmann::json recipe = {{"passes", {{{"name", "gbuffer"}, {"type", "gbuffer"}}}},
                                 {"outputs", {"gbuffer.hits", "gbuffer.normal"}}};
  constexpr int w = 160, h = 120;
  auto f = testing::renderHybridFrame(scene, w, h, {}, parseRecipe(recipe, "test"));
  const CpuImage& hits = f->output("gbuffer.hits");
  const CpuImage& normal = f->output("gbuffer.normal");
  std::vector<double> parity;
  int detailed = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto hit = hitsTexel(hits, x, y);
      if (!hit) continue;
      const vec3 dir = primaryRay(f->scene.camera, w, h, x + 0.5f, y + 0.5f).direction;
      const SurfacePoint p = makeSurfacePoint(f->scene, f->world->geometry(), *hit, dir);
      const SurfacePoint q = makeSurfacePoint(flat, f->world->geometry(), *hit, dir);
      // The CPU's normals face the ray; the G-buffer's are unflipped (CCW front).
      const float side = p.frontFacing ? 1.f : -1.f;
      const vec3 g = glm::normalize(vec3(normal.f(x, y, 0), normal.f(x, y, 1), normal.f(x, y, 2)));
      auto angle = [](vec3 a, vec3 b) {
        return double(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
      };
      parity.push_back(angle(g, side * p.shadingNormal));
      if (angle(g, side * q.shadingNormal) > 0.02) ++detailed;
    }
  Angles a;
  a.pixels = int(parity.size());
  if (parity.empty()) return a;
  std::sort(parity.begin(), parity.end());
  a.parityP99 = parity[parity.size() * 99 / 100];
  a.parityMax = parity.back();
  a.detailShare = double(detailed) / double(parity.size());
  return a;
}

TEST(GBufferDetailNormal, NormalOutputIsTheBumpOrNormalMappedShadingNormal) {
  const Scene bumped = tessellateAnalytic(
      loadScene(fs::path(DIPTYCH_SAMPLES_DIR) / "scenes/surface-detail.json"), 96);
  for (const SurfaceDetail mode : {SurfaceDetail::Bump, SurfaceDetail::NormalMap}) {
    const Angles a =
        measure(withSurfaceDetail(bumped, mode), withSurfaceDetail(bumped, SurfaceDetail::Flat));
    const char* name = mode == SurfaceDetail::Bump ? "bump" : "normal map";
    std::printf(
        "[ measured ] %s: %d pixels, GL vs CPU normal p99 %.3g rad, max %.3g rad; %.1f%% "
        "of pixels > 0.02 rad off the vertex normal\n",
        name, a.pixels, a.parityP99, a.parityMax, 100.0 * a.detailShare);
    ASSERT_GT(a.pixels, 5000) << name;
    // GL and C++ evaluate the same bump.glsl / normal-map code on the same texels (BumpGl.*).
    EXPECT_LT(a.parityP99, 1e-3) << name;
    EXPECT_GT(a.detailShare, 0.3) << name;
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
