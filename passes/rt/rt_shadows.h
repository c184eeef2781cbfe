#pragma once
#include "engine/graph/pass.h"

namespace diptych {

// Exact light visibility: one Embree occlusion ray per pixel per light from the G-buffer hit
// (engine/rt/shadow_rays.h: ULP-offset origin, relative stop short of the light), traced as
// ray streams in parallel tiles. Area lights are sampled with `area_samples` stratified rays
// (default 16; 1 = the light's centre only). Output: visibility R32F, one layer per light
// (1 = lit).
class RtShadowsPass : public Pass {
 public:
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  int areaSamples_ = 16;
  ResourceId gbuffer_ = kNoResource, visibility_ = kNoResource;
};

}  // namespace diptych
