#pragma once
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
// Nothing is traced for it on a scene without colour-textured materials (SceneNeed).
// Params: rt_distributed's, with spp 1 by default, and texture_samples. Outputs: color RGBA32F,
// and sdf_steps where the scene has SDF objects (passes/rt/sdf_steps.h).
class RtWhittedPass : public RtDistributedPass {
 public:
  RtWhittedPass() : RtDistributedPass(false) {}
  static ParamSchema schema();
};

}  // namespace diptych
