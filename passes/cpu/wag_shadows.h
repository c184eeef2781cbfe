#pragma once
#include "engine/graph/pass.h"
#include "passes/slots.h"

namespace diptych {

// Light visibility by the lecture's object-precision shadows, the Weiler-Atherton-Greenberg
// algorithm (Tema 5; Atherton, Weiler and Greenberg, "Polygon Shadow Generation", SIGGRAPH 1978):
// hidden surfaces removed from each light by polygon clipping, so that every triangle carries its
// lit parts as detail polygons (engine/scene/lit_polygons.h); the frame then reads, per pixel, the
// G-buffer's triangle and whether its point lies in one of that triangle's lit pieces. Exact for
// polygons (no resolution, no bias beyond a 1e-6 relative depth margin); analytic shapes cast and
// receive as their tessellation (what the rasterizer draws), so their silhouettes differ from
// rt_shadows' by the tessellation's error. Point, spot and area lights from their centre (hard
// shadows), directional lights along their direction; alpha-masked casters cast whole triangles.
// The lit polygons depend on scene and lights, not on the camera: `update` "static" builds them
// once per world (a one-time cost, as a static shadow map), "every_frame" in every frame (what a
// moving light or object pays). docs/shadow-maps.md, "Object-precision shadows".
class WagShadowsPass : public Pass {
 public:
  static ParamSchema schema();
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;
  bool readsHitTriangles() const override { return true; }  // the lit pieces are triangles'

 private:
  bool everyFrame_ = false;
  SlotIo io_;
};

}  // namespace diptych
