#include "passes/registry.h"

#include "passes/raster/gbuffer.h"
#include "passes/raster/shadow_map.h"
#include "passes/rt/rt_shadows.h"
#include "passes/rt/shade.h"

namespace diptych {

const PassRegistry& builtinPasses() {
  static const PassRegistry registry = [] {
    PassRegistry r;
    r.add<GBufferPass>("gbuffer",
                       "rasterized visibility buffer, normals and reversed-Z depth (GL)");
    r.add<RtShadowsPass>("rt_shadows", "exact light visibility by Embree shadow rays (CPU)");
    r.add<ShadowMapPass>("shadow_map", "light visibility by shadow maps with bias and filter modes (GL)");
    r.add<ShadePass>("shade", "the lecture's illumination model from the G-buffer (CPU)");
    return r;
  }();
  return registry;
}

Recipe defaultHybridRecipe() {
  Recipe recipe;
  recipe.file = "<built-in hybrid recipe>";
  recipe.passes = {
      {.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
      {.name = "shadows",
       .type = "rt_shadows",
       .inputs = {{"visibility", "gbuffer.visibility"}},
       .place = "passes[1]"},
      {.name = "shade",
       .type = "shade",
       .inputs = {{"visibility", "gbuffer.visibility"}, {"light_visibility", "shadows.visibility"}},
       .place = "passes[2]"},
  };
  recipe.outputs = {"shade.color"};
  return recipe;
}

}  // namespace diptych
