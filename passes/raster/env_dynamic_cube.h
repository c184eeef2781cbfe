#pragma once
#include "engine/graph/pass.h"
#include "passes/slots.h"

namespace diptych {

// Reflection-slot producer: a dynamic cube (box) map (Tema 5, "Mapas de entorno tipo caja":
// the environment projected on the six faces of a cube centred on the reflective object),
// captured every frame by forward-rendering the scene without that object from the centre of
// its bounds, `resolution` x `resolution` per face (default 256). One capture per reflective
// instance (material k_ps > 0); its pixels look the cube up along r = reflect(-v, n) at the
// exact G-buffer point. The lookup treats the captured scene as infinitely far: the parallax
// error grows with the distance between the surface point and the centre, relative to the
// distance to what is reflected (docs/forward-producers.md). 0 elsewhere.
class EnvDynamicCubePass : public Pass {
 public:
  static ParamSchema schema();
  Domain domain() const override { return Domain::Gl; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  int resolution_ = 256;
  bool textureLod_ = true;  // texture_lod (passes/raster/forward_texture_lod.h)
  SlotIo io_;
  ResourceId surface_ = kNoResource;
};

}  // namespace diptych
