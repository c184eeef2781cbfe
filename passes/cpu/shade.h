#pragma once
#include "engine/graph/placeable_pass.h"

namespace diptych {

// The lecture's local illumination model from the G-buffer, on the CPU with the shared shading
// code (shaders/common/shading.glsl compiled as C++):
//   L = M_E + A_G + sum_i V_i S_i (k_a C + k_d C max(0, n.l) + k_s d_i max(0, r.v)^e)
//       + k_ps M_PS L_refl + k_t M_T L_trans
// V_i comes from the light_visibility input (any producer of the visibility slot; 1 when
// unconnected or culled); L_refl and L_trans from optional reflection/transmission inputs
// (0 when unconnected); `albedo` (the texture-filtering slot's signal), when connected,
// replaces the resolved material's C and alpha
// (its own level-0 lookup where absent or -1). Background pixels show the environment.
// Output: color RGBA32F.
//
// Shade exists in both domains: the same model runs on GL (passes/raster/gl_shade.h) from the
// same shared code. Parameter `domain` = auto (the compiler places it where its inputs live,
// docs/frame-graph.md "Placement"), gl or cpu.
class ShadePass : public PlaceablePass {
 public:
  static ParamSchema schema();
  Domain domain() const override { return domain_; }
  bool autoPlaced() const override { return auto_; }
  void place(Domain domain) override { domain_ = domain; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  Domain domain_ = Domain::Cpu;
  bool auto_ = false;
  ResourceId hits_ = kNoResource, surface_ = kNoResource, lightVisibility_ = kNoResource;
  ResourceId reflection_ = kNoResource, transmission_ = kNoResource, color_ = kNoResource;
  ResourceId albedo_ = kNoResource, depth_ = kNoResource;  // depth_: the G-buffer's, GL only
};

}  // namespace diptych
