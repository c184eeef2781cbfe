#pragma once
#include <vector>

#include "engine/graph/pass.h"
#include "engine/scene/world_geometry.h"
#include "passes/slots.h"

namespace diptych {

// Reflection-slot producer for plane mirrors (Tema 5, "Reflexión en espejos planos": the
// reflected scene is the original mirrored about the mirror's plane, seen by a symmetric
// camera). One mirror per planar reflective instance (material k_ps > 0, all vertices on one
// plane): the scene, without the mirror itself, is forward-rendered with the view mirrored
// about the plane and clipped to the camera's side of it by a user clip plane
// (gl_ClipDistance), at frame size; each G-buffer pixel of that instance reads the mirrored
// render at the same pixel. 0 elsewhere (non-planar reflective objects included).
// Params: texture_lod (passes/raster/forward_texture_lod.h).
class PlanarMirrorPass : public Pass {
 public:
  static ParamSchema schema();
  Domain domain() const override { return Domain::Gl; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  SlotIo io_;
  bool textureLod_ = true;
};

struct MirrorPlane {
  int instance = -1;
  vec3 normal{0.f};    // unit, the face normal of the largest triangle (either side may face you)
  float offset = 0.f;  // plane: dot(normal, x) + offset = 0
};

// The planar reflective instances. A mesh is planar when every vertex lies within
// 64 ulp-scale units of the plane of its largest triangle: 64 FLT_EPSILON times the mesh's
// largest coordinate magnitude plus its extent (a relative tolerance: the rounding of the
// flattened world positions scales with their magnitude; no world-space epsilon).
std::vector<MirrorPlane> findPlanarMirrors(const Scene& scene, const WorldGeometry& world);

// Affine reflection about the plane dot(n, x) + d = 0 (n unit): x' = x - 2 (n.x + d) n.
mat4 reflectionMatrix(const vec3& n, float d);

}  // namespace diptych
