#pragma once
#include "engine/graph/pass.h"
#include "passes/raster/shadow_map_settings.h"

namespace diptych {

// Light visibility by Z-buffer shadow maps (docs/shadow-maps.md): a D32F reversed-Z map per
// directional (orthographic) and spot (perspective) light and a 6-face cube per point or area
// light, rendered from the scene's GPU buffers; then a full-screen lookup from the exact G-buffer
// surface point with the chosen bias (none, constant, slope, normal_offset, receiver_plane,
// adaptive) and filter (none, pcf, poisson, pcss). Output: visibility R32F, one layer per light.
class ShadowMapPass : public Pass {
 public:
  Domain domain() const override { return Domain::Gl; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  shadowmap::Settings settings_;
  ResourceId gbuffer_ = kNoResource, visibility_ = kNoResource;
};

}  // namespace diptych
