// rt_distributed traces its sample rays in tiles of 64 (RtScene::intersectRays, then
// WhittedTracer::radianceTile) and sums each pixel's samples in their order: against the
// ray-by-ray Whitted recursion over the same sample rays, rebuilt here from the pass's
// documented sampling rather than from its code.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "engine/graph/executor.h"
#include "engine/graph/render_world.h"
#include "engine/rt/light_sampling.h"
#include "engine/rt/whitted.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/load.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

TEST(DistributedTiles, AverageRadianceOverLensSamples) {
  // rt_distributed at spp 4 with a lens: the tiles of 64 sample rays (pixelOf, seeds, the
  // per-pixel lens shuffle) against radiance() over the same rays, written out here from the
  // pass's sampling (stratified pixel and lens samples, Cook et al. 1984). Its hits come from
  // streams: pixels may differ by the packet kernels' rounding (budget: 0.1% of pixels).
  Scene scene = loadScene(DIPTYCH_SAMPLES_DIR + "/scenes/whitted.json");
  scene.camera.aperture = 0.15f;
  scene.camera.focusDistance = 6.f;
  constexpr int w = 64, h = 48, spp = 4;
  Recipe recipe;
  recipe.file = "test";
  RecipePass p;
  p.name = "d";
  p.type = "rt_distributed";
  p.params = {{"spp", spp}, {"depth", 5}, {"area_samples", 4}};
  p.place = "passes[0]";
  recipe.passes = {p};
  recipe.outputs = {"d.color"};
  const CompiledGraph g = compileGraph(recipe, builtinPasses(), scene, {w, h, scene.camera});
  RenderWorld world(scene);
  GraphExecutor ex(g, world);
  ex.runFrame();
  const CpuImage& image = ex.output("d.color");
  const WhittedTracer tracer(scene, world.geometry(), world.rtScene(), {5, 4, false});
  int differ = 0;
  std::vector<int> lensStratum(spp);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::uint32_t pixel = std::uint32_t(y * w + x);
      // Fisher-Yates by pcgHash, seeded by the pixel and "LENS".
      std::iota(lensStratum.begin(), lensStratum.end(), 0);
      std::uint32_t shuffleSeed = pcgHash(pixel ^ 0x4c454e53u);
      for (std::size_t i = lensStratum.size(); i > 1; --i) {
        shuffleSeed = pcgHash(shuffleSeed);
        std::swap(lensStratum[i - 1], lensStratum[shuffleSeed % i]);
      }
      vec3 sum(0.f);
      for (int s = 0; s < spp; ++s) {
        const vec2 offset = stratifiedSample(s, spp, pcgHash(pixel));
        const vec2 lens =
            stratifiedSample(lensStratum[std::size_t(s)], spp, pcgHash(pixel ^ 0x4c454e53u));
        const Ray ray =
            thinLensRay(scene.camera, w, h, float(x) + offset.x, float(y) + offset.y, lens);
        sum += tracer.radiance(ray, 1, pcgHash(pixel * 4096u + std::uint32_t(s)));
      }
      const vec3 expected = sum / float(spp);
      const vec3 got(image.f(x, y, 0), image.f(x, y, 1), image.f(x, y, 2));
      differ += got == expected ? 0 : 1;
    }
  }
  EXPECT_LE(differ, (w * h + 999) / 1000);
}

}  // namespace DIPTYCH_UNITY_ID
