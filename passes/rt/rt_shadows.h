#pragma once
#include "engine/graph/pass.h"

namespace diptych {

// Exact light visibility: one Embree occlusion ray per pixel per light from the G-buffer hit
// (engine/rt/shadow_rays.h: ULP-offset origin, relative stop short of the light), traced as
// ray streams in parallel tiles. Output: visibility R32F, one layer per light (1 = lit).
class RtShadowsPass : public Pass {
 public:
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  ResourceId gbuffer_ = kNoResource, visibility_ = kNoResource;
};

}  // namespace diptych
