// The lecture's bump mapping on the GL side (shaders/gl/scene_shading.glsl sceneBumpMapped, used
// by surfaceFromHits and forward.frag) against the CPU's (makeSurfacePoint): GL shade and CPU
// shade in one frame on the same G-buffer and signals, on samples/scenes/surface-detail.json with
// its sphere tessellated (GL shades triangles; analytic shapes are lifted only on the CPU), once
// with the procedural sinusoids and once with the sphere's height in a texture. Norm as in
// test_gl_shade.cpp: relative RMSE over the RGB of every pixel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "engine/scene/primitives.h"
#include "engine/shading/surface_detail.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

namespace fs = std::filesystem;

constexpr double kParityBound =
    1e-4;  // as GlShade.MatchesCpuShadeOnEverySampleWithTheSameProducers

double relativeRmse(const CpuImage& a, const CpuImage& b) {
  double d = 0, r = 0;
  for (int y = 0; y < b.desc.height; ++y)
    for (int x = 0; x < b.desc.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double e = double(a.f(x, y, c)) - b.f(x, y, c);
        d += e * e, r += double(b.f(x, y, c)) * b.f(x, y, c);
      }
  return r > 0 ? std::sqrt(d / r) : HUGE_VAL;
}

Scene detailScene(bool heightTexture) {
  Scene scene = tessellateAnalytic(
      loadScene(fs::path(DIPTYCH_SAMPLES_DIR) / "scenes/surface-detail.json"), 96);
  if (heightTexture) {  // the ball's relief from a 128^2 greyscale texture instead
    constexpr int n = 128;
    Texture t;
    t.name = "height";
    t.image = Image(n, n, 4, 1.f);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const float u = (x + 0.5f) / n, v = (y + 0.5f) / n;
        const float h = 0.5f + 0.25f * std::sin(6.2831853f * 12.f * u + 3.f * std::sin(9.f * v)) *
                                   std::cos(6.2831853f * 5.f * v);
        for (int c = 0; c < 3; ++c) t.image.at(x, y, c) = h;
      }
    scene.textures.push_back(std::move(t));
    for (Material& m : scene.materials)
      if (m.name == "ball")
        m.bump = BumpMap{int(scene.textures.size()) - 1, 0.f, vec2(1.f), 0.08f, 1.f / n};
  }
  return scene;
}

TEST(BumpGl, GlShadeMatchesCpuShadeOnBumpMappedSurfaces) {
  for (const bool texture : {false, true})
    for (const char* recipeName : {"raster", "hybrid"}) {
      SCOPED_TRACE(std::string(recipeName) + (texture ? " / height texture" : " / sinusoid"));
      const Recipe recipe = testing::withShadeInBothDomains(loadRecipe(
          fs::path(DIPTYCH_SAMPLES_DIR) / "graphs" / (std::string(recipeName) + ".json")));
      auto f = testing::renderHybridFrame(detailScene(texture), 160, 120, {}, recipe);
      const double parity = relativeRmse(f->output("shade_gl.color"), f->output("shade_cpu.color"));
      std::printf("[ measured ] bump %-7s %-8s GL vs CPU shade relative RMSE %.3g\n",
                  texture ? "texture" : "sinusoid", recipeName, parity);
      EXPECT_LE(parity, kParityBound);
    }
}

// Not vacuous: on GL the bump changes the frame (against the same scene without it) by far more
// than the parity bound.
TEST(BumpGl, BumpChangesTheGlFrame) {
  const Recipe recipe = loadRecipe(fs::path(DIPTYCH_SAMPLES_DIR) / "graphs/raster.json");
  const Scene bumped = detailScene(false);
  auto b = testing::renderHybridFrame(bumped, 160, 120, {}, recipe);
  auto flat = testing::renderHybridFrame(withSurfaceDetail(bumped, SurfaceDetail::Flat), 160, 120,
                                         {}, recipe);
  const double change =
      relativeRmse(b->output(recipe.outputs.front()), flat->output(recipe.outputs.front()));
  std::printf("[ measured ] GL frame with vs without bump: relative RMSE %.3g\n", change);
  EXPECT_GT(change, 0.05);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
