#pragma once
#include "engine/graph/pass.h"
#include "engine/rt/shadow_rays.h"
#include "passes/slots.h"

namespace diptych {

// Exact light visibility: one Embree occlusion ray per pixel per light from the G-buffer hit
// (engine/rt/shadow_rays.h: ULP-offset origin, relative stop short of the light), traced as
// coherent ray streams row by row (traceShadowTile). Area lights are sampled with `area_samples`
// stratified rays (schema()). Output: the visibility slot's signal (passes/slots.cpp).
class RtShadowsPass : public Pass {
 public:
  static ParamSchema schema();
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  int areaSamples_ = 16;
  SlotIo io_;
};

}  // namespace diptych
