#include "passes/registry.h"

#include "passes/raster/blend_transmission.h"
#include "passes/raster/dynamic_cube.h"
#include "passes/raster/env_reflection.h"
#include "passes/raster/gbuffer.h"
#include "passes/raster/planar_mirror.h"
#include "passes/raster/shadow_map.h"
#include "passes/rt/rt_distributed.h"
#include "passes/rt/rt_path.h"
#include "passes/rt/rt_secondary.h"
#include "passes/rt/rt_shadows.h"
#include "passes/rt/rt_whitted.h"
#include "passes/rt/shade.h"

namespace diptych {

const PassRegistry& builtinPasses() {
  static const PassRegistry registry = [] {
    PassRegistry r;
    r.add<GBufferPass>("gbuffer",
                       "rasterized visibility buffer, normals and reversed-Z depth (GL)");
    r.add<SortedBlendPass>("sorted_blend",
                           "transmission by the lecture's Z-buffer blending, back to front (GL)");
    r.add<UnsortedBlendPass>("unsorted_blend",
                             "transmission by Z-buffer blending in scene order (GL)");
    r.add<PlanarMirrorPass>("planar_mirror", "reflection by the camera mirrored about planes (GL)");
    r.add<DynamicCubePass>("env_dynamic_cube",
                           "reflection by a cube map captured from the object's centre (GL)");
    r.add<EnvCubePass>("env_cube", "reflection: environment cube map lookup along r (GL)");
    r.add<EnvSpherePass>("env_sphere",
                         "reflection: sphere map (GL_SPHERE_MAP) lookup along r (GL)");
    r.add<EnvEquirectPass>("env_equirect", "reflection: lat-long panorama lookup along r (GL)");
    r.add<RtShadowsPass>("rt_shadows", "exact light visibility by Embree shadow rays (CPU)");
    r.add<RtReflectionPass>("rt_reflection",
                            "exact reflection: recursive Whitted reflection rays (CPU)");
    r.add<RtTransmissionPass>("rt_transmission",
                              "exact transmission: recursive refraction rays (CPU)");
    r.add<RtWhittedPass>("rt_whitted",
                         "full ray tracing: the Whitted reference from primary rays (CPU)");
    r.add<ShadowMapPass>("shadow_map",
                         "light visibility by shadow maps with bias and filter modes (GL)");
    r.add<RtDistributedPass>(
        "rt_distributed",
        "distributed ray tracing (Cook 1984): antialiasing, depth of field, soft shadows (CPU)");
    r.add<RtPathPass>("rt_path", "path-traced global-illumination reference (Kajiya 1986) (CPU)");
    r.add<ShadePass>("shade", "the lecture's illumination model from the G-buffer (CPU)");
    return r;
  }();
  return registry;
}

Recipe defaultHybridRecipe() {
  Recipe recipe;
  recipe.file = "<built-in hybrid recipe>";
  const std::map<std::string, std::string> fromGbuffer = {{"visibility", "gbuffer.visibility"}};
  recipe.passes = {
      {.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
      {.name = "shadows", .type = "rt_shadows", .inputs = fromGbuffer, .place = "passes[1]"},
      {.name = "reflection", .type = "rt_reflection", .inputs = fromGbuffer, .place = "passes[2]"},
      {.name = "transmission",
       .type = "rt_transmission",
       .inputs = fromGbuffer,
       .place = "passes[3]"},
      {.name = "shade",
       .type = "shade",
       .inputs = {{"visibility", "gbuffer.visibility"},
                  {"light_visibility", "shadows.visibility"},
                  {"reflection", "reflection.reflection"},
                  {"transmission", "transmission.transmission"}},
       .place = "passes[4]"},
  };
  recipe.outputs = {"shade.color"};
  return recipe;
}

}  // namespace diptych
