#pragma once
#include "engine/graph/pass.h"

namespace diptych {

// Full ray tracing: the exact producer of the primary-visibility slot and the Whitted reference
// (engine/rt/whitted.h). One primary ray per pixel through its centre by default, so that it
// compares pixel for pixel with the raster G-buffer; `spp` > 1 supersamples each pixel with a
// stratified k x k jittered grid (k^2 = spp rounded to a square) and averages (box filter).
// Params: depth (5), area_samples (16), spp (1). Output: color RGBA32F.
class RtWhittedPass : public Pass {
 public:
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  int maxDepth_ = 5, areaSamples_ = 16, spp_ = 1;
  ResourceId color_ = kNoResource;
};

}  // namespace diptych
