#pragma once
#include "engine/graph/pass.h"
#include "passes/slots.h"

namespace diptych {

// Light visibility by the lecture's brute-force shadow polygons (Tema 5, "Algoritmo de fuerza
// bruta": each caster polygon projected from the light onto a receiver polygon), at image
// precision: every shadow-casting triangle is projected from the light onto the plane of each
// planar receiver (the shadow matrix S = (P.L) I - L P^T of Blinn 1988, "Me and my (fake)
// shadow", in the well-conditioned form of shaders/common/shadow_projection.glsl), clipped to the
// slab between the plane and the light (only points there can block a receiver point's segment to
// the light), and drawn through the camera; where a projected polygon covers a pixel whose G-buffer
// point lies on that receiver, V_i = 0. Receivers are the planar instances (planar_instances.h);
// every other surface keeps V_i = 1: the technique's limit the lecture states (one receiver
// polygon, a few casters), which its error against rt_shadows shows. Point, spot and area lights
// project from their centre (hard shadows), directional lights along their direction. Alpha-masked
// casters cast their whole triangles. No parameters. docs/shadow-maps.md, "Shadow polygons on
// planar receivers".
class PlanarShadowsPass : public Pass {
 public:
  Domain domain() const override { return Domain::Gl; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  SlotIo io_;
};

}  // namespace diptych
