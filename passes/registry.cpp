#include "passes/registry.h"

#include "engine/core/error.h"
#include "passes/cpu/no_shadows.h"
#include "passes/cpu/shade.h"
#include "passes/cpu/wag_shadows.h"
#include "passes/raster/env_cube.h"
#include "passes/raster/env_dynamic_cube.h"
#include "passes/raster/env_equirect.h"
#include "passes/raster/env_sphere.h"
#include "passes/raster/gbuffer.h"
#include "passes/raster/planar_mirror.h"
#include "passes/raster/planar_shadows.h"
#include "passes/raster/shadow_map.h"
#include "passes/raster/sorted_blend.h"
#include "passes/raster/texture_anisotropic.h"
#include "passes/raster/texture_bilinear.h"
#include "passes/raster/texture_distance.h"
#include "passes/raster/texture_nearest.h"
#include "passes/raster/texture_sampler.h"
#include "passes/raster/texture_trilinear.h"
#include "passes/raster/unsorted_blend.h"
#include "passes/rt/rt_distributed.h"
#include "passes/rt/rt_path.h"
#include "passes/rt/rt_reflection.h"
#include "passes/rt/rt_shadows.h"
#include "passes/rt/rt_transmission.h"
#include "passes/rt/rt_whitted.h"
#include "passes/rt/texture_supersample.h"
#include "passes/slots.h"

namespace diptych {

const PassRegistry& builtinPasses() {
  static const PassRegistry registry = [] {
    PassRegistry r;
    r.add<GBufferPass>(
        {.name = "gbuffer",
         .summary =
             "rasterized hits buffer, normals, optional stored surface, reversed-Z depth (GL)"});
    r.addRenamedOutput({"gbuffer", "visibility", kHits});
    r.add<ShadePass>({.name = "shade",
                      .summary = "the lecture's illumination model from the G-buffer (GL or CPU: "
                                 "placed where its inputs live)"});

    // Producers by slot; within a slot, `diptych compare` runs them in this order.
    r.add<RtShadowsPass>({.name = "rt_shadows",
                          .slot = "visibility",
                          .summary = "exact light visibility by Embree shadow rays (CPU); 1, with "
                                     "no ray, where the light sends the point nothing"});
    r.add<ShadowMapPass>(
        {.name = "shadow_map",
         .slot = "visibility",
         .summary = "light visibility by shadow maps with bias and filter modes (GL)",
         .presets = {{"shadow-map-256-none", "resolution=256,bias=none"},
                     {"shadow-map-1024-constant", "resolution=1024,bias=constant"},
                     {"shadow-map-2048-slope", "resolution=2048,bias=slope,factor=2,units=2"},
                     {"shadow-map-2048-normal-offset", "resolution=2048,bias=normal_offset"},
                     {"shadow-map-2048-receiver-plane-pcf",
                      "resolution=2048,bias=receiver_plane,filter=pcf,kernel=3"},
                     {"shadow-map-2048-adaptive", "resolution=2048,bias=adaptive"},
                     {"shadow-map-4096-slope-pcss",
                      "resolution=4096,bias=slope,factor=2,units=2,filter=pcss"}}});
    r.add<PlanarShadowsPass>(
        {.name = "planar_shadows",
         .slot = "visibility",
         .summary = "light visibility by shadow polygons projected onto planar receivers (GL)"});
    r.add<WagShadowsPass>(
        {.name = "wag_shadows",
         .slot = "visibility",
         .summary = "light visibility by object-precision shadows: lit polygons clipped from "
                    "the light, Weiler-Atherton-Greenberg (CPU)",
         .presets = {{"wag-shadows", "update=static"},
                     {"wag-shadows-per-frame", "update=every_frame"}}});
    r.add<NoShadowsPass>({.name = "no_shadows",
                          .slot = "visibility",
                          .summary = "no shadows: V_i = 1 everywhere, the baseline (CPU)"});
    r.add<RtReflectionPass>(
        {.name = "rt_reflection",
         .slot = "reflection",
         .summary = "exact reflection: recursive Whitted reflection rays (CPU)"});
    r.add<EnvCubePass>({.name = "env_cube",
                        .slot = "reflection",
                        .summary = "reflection: environment cube map lookup along r (GL)"});
    r.add<EnvSpherePass>({.name = "env_sphere",
                          .slot = "reflection",
                          .summary = "reflection: sphere map (GL_SPHERE_MAP) lookup along r (GL)"});
    r.add<EnvEquirectPass>({.name = "env_equirect",
                            .slot = "reflection",
                            .summary = "reflection: lat-long panorama lookup along r (GL)"});
    r.add<EnvDynamicCubePass>(
        {.name = "env_dynamic_cube",
         .slot = "reflection",
         .summary = "reflection by a cube map captured from the object's centre (GL)"});
    r.add<PlanarMirrorPass>({.name = "planar_mirror",
                             .slot = "reflection",
                             .summary = "reflection by the camera mirrored about planes (GL)"});
    r.add<RtTransmissionPass>({.name = "rt_transmission",
                               .slot = "transmission",
                               .summary = "exact transmission: recursive refraction rays (CPU)"});
    r.add<SortedBlendPass>(
        {.name = "sorted_blend",
         .slot = "transmission",
         .summary = "transmission by the lecture's Z-buffer blending, back to front (GL)"});
    r.add<UnsortedBlendPass>({.name = "unsorted_blend",
                              .slot = "transmission",
                              .summary = "transmission by Z-buffer blending in scene order (GL)"});
    r.add<TextureSupersamplePass>(
        {.name = "texture_supersample",
         .slot = "texture_filtering",
         .summary = "exact texture filtering: N x N stratified sub-pixel rays, level 0 (CPU)"});
    r.add<TextureNearestPass>({.name = "texture_nearest",
                               .slot = "texture_filtering",
                               .summary = "texture: nearest texel of level 0, no mipmaps (GL)"});
    r.add<TextureBilinearPass>({.name = "texture_bilinear",
                                .slot = "texture_filtering",
                                .summary = "texture: bilinear on level 0, no mipmaps (GL)"});
    r.add<TextureDistancePass>(
        {.name = "texture_distance",
         .slot = "texture_filtering",
         .summary = "texture: the lecture's mip level from log2 of the eye distance (GL)"});
    r.add<TextureTrilinearPass>(
        {.name = "texture_trilinear",
         .slot = "texture_filtering",
         .summary = "texture: GL's derivative-based level, trilinear (GL)"});
    r.add<TextureAnisotropicPass>(
        {.name = "texture_anisotropic",
         .slot = "texture_filtering",
         .summary = "texture: anisotropic probes along the footprint's long axis (GL)"});
    r.add<TextureSamplerPass>(
        {.name = "texture_sampler",
         .slot = "texture_filtering",
         .summary = "texture: its own glTF sampler (min/mag, mip mode) at GL's level (GL)"});

    // Full-frame references (no slot).
    r.add<RtWhittedPass>(
        {.name = "rt_whitted",
         .summary = "full ray tracing: the Whitted reference from primary rays (CPU)"});
    r.add<RtDistributedPass>(
        {.name = "rt_distributed",
         .summary = "distributed ray tracing (Cook 1984): antialiasing, depth of field, soft "
                    "shadows (CPU)"});
    r.add<RtPathPass>({.name = "rt_path",
                       .summary = "path-traced global-illumination reference (Kajiya 1986) (CPU)"});

    for (const PassTypeInfo& t : r.all())
      if (!t.slot.empty() && !findTechniqueSlot(t.slot))
        throw Error("pass type '" + t.name + "' names an undeclared slot '" + t.slot + "'");
    for (const TechniqueSlot& s : techniqueSlots())
      if (!r.find(s.exact) || r.find(s.exact)->slot != s.name)
        throw Error("slot '" + s.name + "': exact producer '" + s.exact + "' not registered");
    return r;
  }();
  return registry;
}

}  // namespace diptych
