#pragma once
#include "engine/graph/pass.h"

namespace diptych {

// Distributed ray tracing (R. L. Cook, T. Porter, L. Carpenter, "Distributed Ray Tracing",
// SIGGRAPH 1984; the lecture's "Ray-Tracing distribuido"): each pixel averages `spp` primary
// rays distributed over the pixel area (antialiasing, a stratified k x k jittered grid, box
// filter), over the lens disc (thin-lens depth of field from Camera::aperture, the lens radius,
// and Camera::focusDistance; aperture 0 is a pinhole), over the shutter where an instance moves
// (motion blur: Instance::motion; each sample's time, a per-pixel permutation of spp jittered
// strata, is kept by every ray of its tree), and, through the Whitted tracer, over the area
// lights (stratified shadow rays, `area_samples` per light per hit). Everything after the
// primary ray is WhittedTracer (engine/rt/whitted.h): the same recursion and shading.
// With spp = 1 the single ray goes through the pixel centre with the pixel index as its seed,
// so that spp = 1 and aperture 0 reproduce rt_whitted bit for bit on a static scene (where
// something moves, its time is still drawn from the shutter).
// Params: schema() (`diptych passes` lists them). Output: color RGBA32F, and sdf_steps
// (passes/rt/sdf_steps.h) where the scene has SDF objects.
class RtDistributedPass : public Pass {
 public:
  RtDistributedPass() = default;
  static ParamSchema schema(int defaultSpp = 16);
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 protected:
  // rt_whitted is this pass with one sample by default and a pinhole whatever the aperture.
  explicit RtDistributedPass(bool thinLens) : thinLens_(thinLens) {}

 private:
  bool thinLens_ = true;
  int spp_ = 16, maxDepth_ = 5, areaSamples_ = 16;
  bool rayCones_ = false;
  int textureSamples_ = 1;  // rt_whitted's texture_samples (rt_whitted.h)
  ResourceId color_ = kNoResource;
  ResourceId sdfSteps_ = kNoResource;  // passes/rt/sdf_steps.h; only with SDF objects
};

}  // namespace diptych
