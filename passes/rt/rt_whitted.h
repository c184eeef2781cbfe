#pragma once
#include "passes/rt/rt_distributed.h"

namespace diptych {

// Full ray tracing: the exact producer of the primary-visibility slot and the Whitted reference
// (engine/rt/whitted.h: the lecture's RAYTRACING / EVALUAMILREC / DIRECTA). One primary ray per
// pixel through its centre by default, so that it compares pixel for pixel with the raster
// G-buffer; `spp` > 1 supersamples each pixel with a stratified k x k jittered grid (k^2 = spp
// rounded to a square) and averages (box filter). Always a pinhole camera. It is
// rt_distributed with those two settings: one code path for primary rays.
// Params: rt_distributed's, with spp 1 by default. Outputs: color RGBA32F, and sdf_steps where the
// scene has SDF objects (passes/rt/sdf_steps.h).
class RtWhittedPass : public RtDistributedPass {
 public:
  RtWhittedPass() : RtDistributedPass(false) {}
  static ParamSchema schema() { return RtDistributedPass::schema(1); }
};

}  // namespace diptych
