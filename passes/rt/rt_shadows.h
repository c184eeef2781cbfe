#pragma once
#include <cstdint>
#include <vector>

#include "engine/graph/pass.h"
#include "engine/rt/shadow_rays.h"
#include "passes/slots.h"

namespace diptych {

// Exact light visibility: one Embree occlusion ray per pixel per light from the G-buffer hit
// (engine/rt/shadow_rays.h: ULP-offset origin, relative stop short of the light), traced as
// ray streams in parallel tiles. Area lights are sampled with `area_samples` stratified rays
// (schema()). Output: the visibility slot's signal (passes/slots.cpp).
class RtShadowsPass : public Pass {
 public:
  static ParamSchema schema();
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  int areaSamples_ = 16;
  SlotIo io_;
  // Per-frame arrays kept across frames (same size each frame: no allocation, no page faults).
  std::vector<int> rowCount_;
  std::vector<std::uint32_t> pixelOf_;
  std::vector<ShadowReceiver> receivers_;
};

}  // namespace diptych
