#pragma once
#include "engine/graph/pass.h"

namespace diptych {

// The lecture's local illumination model from the G-buffer, on the CPU with the shared shading
// code (shaders/common/shading.glsl compiled as C++):
//   L = M_E + A_G + sum_i V_i S_i (k_a C + k_d C max(0, n.l) + k_s d_i max(0, r.v)^e)
//       + k_ps M_PS L_refl + k_t M_T L_trans
// V_i comes from the light_visibility input (any producer of the visibility slot; 1 when
// unconnected or culled); L_refl and L_trans from optional reflection/transmission inputs
// (0 when unconnected); C and coverage from the optional albedo input (the texture_filtering
// slot; its own level-0 lookup where absent or -1). Background pixels show the environment.
// Output: color RGBA32F.
class ShadePass : public Pass {
 public:
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  ResourceId hits_ = kNoResource, lightVisibility_ = kNoResource;
  ResourceId reflection_ = kNoResource, transmission_ = kNoResource, color_ = kNoResource;
  ResourceId albedo_ = kNoResource;
};

}  // namespace diptych
