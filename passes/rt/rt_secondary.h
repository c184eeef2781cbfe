#pragma once
// The exact producers of the reflection and transmission slots: from each G-buffer point whose
// material has k_ps > 0 (reflection) or k_t > 0 (transmission), the radiance arriving along the
// mirror or refracted direction, traced recursively by the Whitted tracer (engine/rt/whitted.h)
// with the same shading as everything else. Other pixels get 0. The family of rt_reflection.h
// and rt_transmission.h. Where the scene has SDF objects they also write sdf_steps
// (passes/rt/sdf_steps.h), the sphere-tracing steps of each pixel's secondary ray tree.
// `texture_samples` N > 1 makes them the exact answer for textures seen in a mirror or through
// glass too: the colour at the first textured hit along each pixel's secondary ray is the mean
// over its footprint, N x N sub-pixel rays each followed the same way (SecondaryFootprint,
// passes/rt/texture_supersample.h), as the Whitted reference's texture_samples does; 1 (the
// default): the hit's own lookup (level 0, or a ray cone's level with texture_lod=cone). Nothing
// is traced for it on a scene without colour-textured materials.
#include "engine/graph/pass.h"
#include "passes/slots.h"

namespace diptych {

class RtSecondaryPass : public Pass {
 public:
  enum class Kind { Reflection, Transmission };
  explicit RtSecondaryPass(Kind kind) : kind_(kind) {}
  static ParamSchema schema();
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  Kind kind_;
  int maxDepth_ = 5, areaSamples_ = 16, textureSamples_ = 1;
  bool rayCones_ = false;
  SlotIo io_;
  ResourceId sdfSteps_ = kNoResource;  // passes/rt/sdf_steps.h; only with SDF objects
};

}  // namespace diptych
