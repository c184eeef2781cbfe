#pragma once
#include "engine/graph/pass.h"
#include "passes/slots.h"

namespace diptych {

// Rasterized primary visibility (engine/gl/gbuffer_raster.h): hits RGBA32UI
// (instance + 1, primitive, floatBits(u), floatBits(v)) with Embree-convention barycentrics of
// the pixel-centre ray, shading normal RGBA32F (w = material), reversed-Z D32F depth.
class GBufferPass : public Pass {
 public:
  Domain domain() const override { return Domain::Gl; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  ResourceId hits_ = kNoResource, normal_ = kNoResource, depth_ = kNoResource;
};

}  // namespace diptych
