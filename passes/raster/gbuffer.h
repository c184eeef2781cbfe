#pragma once
#include "engine/graph/adaptive_pass.h"
#include "passes/slots.h"

namespace diptych {

// Rasterized primary visibility (engine/gl/gbuffer_raster.h): hits RGBA32UI
// (instance + 1, primitive, floatBits(u), floatBits(v)) with Embree-convention barycentrics of
// the pixel-centre ray, shading normal RGBA32F (w = material), reversed-Z D32F depth, and the
// surface (RGBA32F, 3 layers: the surface point GL passes read instead of rebuilding it). The
// normal and the surface are written only in frames where a live pass reads them.
// Adaptive (adaptive_pass.h): in a frame where every reader of the hits is a CPU pass (the
// hybrid; the CPU computes (u, v) itself along the pixel ray, hits_texel.h) and nothing reads the
// normal or the surface, the hits are a visibility buffer, (u, v) = NaN.
class GBufferPass : public AdaptivePass {
 public:
  static ParamSchema schema();
  Domain domain() const override { return Domain::Gl; }
  void setup(PassBuilder& builder) override;
  std::string adapt(const ReaderQuery& readers) override;
  void execute(PassContext& context) override;

 private:
  bool barycentrics_ = true;      // adapt()'s choice: false writes the visibility buffer
  bool impostorsAllowed_ = true;  // the "impostors" parameter
  bool impostors_ = false;  // GBufferTargets::impostors: allowed, and no reader needs triangles
  ResourceId hits_ = kNoResource, normal_ = kNoResource,
             surface_ = kNoResource;  // surface_: kNoResource with surface=false
  ResourceId depth_ = kNoResource;
};

}  // namespace diptych
