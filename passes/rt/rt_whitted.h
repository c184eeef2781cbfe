#pragma once
#include <cstdint>
#include <span>

#include "engine/rt/rt_scene.h"
#include "engine/rt/whitted.h"
#include "engine/scene/camera_math.h"
#include "passes/rt/rt_distributed.h"

namespace diptych {

// Full ray tracing: the exact producer of the primary-visibility slot and the Whitted reference
// (engine/rt/whitted.h: the lecture's RAYTRACING / EVALUAMILREC / DIRECTA). One primary ray per
// pixel through its centre by default, so that it compares pixel for pixel with the raster
// G-buffer; `spp` > 1 supersamples each pixel with a stratified k x k jittered grid (k^2 = spp
// rounded to a square) and averages (box filter). Always a pinhole camera. It is
// rt_distributed with those two settings: one code path for primary rays.
// `texture_samples` N > 1 makes it the exact answer of the texture_filtering slot too: each
// pixel's texture colour and coverage are the mean over N x N sub-pixel rays (texture_supersample's
// signal, supersampleTextureRow), applied at the camera ray's hit as the hybrid's shade applies
// that producer's signal (applyTextureSignal), so that rt_whitted with N equals the all-exact
// hybrid with texture_supersample:samples=N; 1 (the default): the pixel centre's own lookup.
// N > 1 also filters the textures the camera hit sees in its mirror or through its glass: the
// colour at the first textured hit along its reflected and refracted rays is the mean over the
// same N x N rays, each followed the same way (SecondaryFootprint, texture_supersample.h), as
// rt_reflection and rt_transmission with texture_samples N do.
// Only pixels whose centre ray hits trace the N x N rays; nothing is traced for it on a scene
// without colour-textured materials (SceneNeed), and it needs spp 1 (an error otherwise: with
// more samples each pixel already integrates its texture).
// Params: rt_distributed's, with spp 1 by default, and texture_samples. Outputs: color RGBA32F,
// and sdf_steps where the scene has SDF objects (passes/rt/sdf_steps.h).
class RtWhittedPass : public RtDistributedPass {
 public:
  RtWhittedPass() : RtDistributedPass(false) {}
  static ParamSchema schema();
};

// Row y of rt_whitted's texture signal into out (the frame's width), and its secondary hits' into
// secondary (the same size; tracer: the one that shades them): its pixel-centre rays traced
// (coherent streams) for coverage, then supersampleTextureRow over the covered pixels (-1
// elsewhere). Returns the rays traced, all kinds.
std::int64_t whittedTextureRow(const Scene& scene, const WorldGeometry& geometry, const RtScene& rt,
                               const PinholeFrame& pinhole, int n, int y, std::span<vec4> out,
                               const WhittedTracer& tracer, std::span<SecondarySignals> secondary);

}  // namespace diptych
