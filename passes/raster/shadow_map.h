#pragma once
#include "engine/graph/pass.h"
#include "passes/raster/shadow_map_settings.h"
#include "passes/slots.h"

namespace diptych {

// Light visibility by Z-buffer shadow maps (docs/shadow-maps.md): a D32F reversed-Z map per
// directional (orthographic) and spot (perspective) light and a 6-face cube per point or area
// light, rendered from the scene's GPU buffers; then a full-screen lookup from the exact G-buffer
// surface point with the chosen bias (none, constant, slope, normal_offset, receiver_plane,
// adaptive) and filter (none, pcf, poisson, pcss). Output: the visibility slot's signal.
class ShadowMapPass : public Pass {
 public:
  static ParamSchema schema() { return shadowmap::schema(); }
  Domain domain() const override { return Domain::Gl; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  shadowmap::Settings settings_;
  SlotIo io_;
  ResourceId surface_ = kNoResource;
};

}  // namespace diptych
