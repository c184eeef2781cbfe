#pragma once
#include <vector>

#include "engine/graph/pass.h"
#include "engine/scene/world_geometry.h"
#include "passes/raster/planar_instances.h"
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

// The planar reflective instances (findPlanarInstances over the meshes whose material reflects).
std::vector<PlanarInstance> findPlanarMirrors(const Scene& scene, const WorldGeometry& world);

// Affine reflection about the plane dot(n, x) + d = 0 (n unit): x' = x - 2 (n.x + d) n.
mat4 reflectionMatrix(const vec3& n, float d);

}  // namespace diptych
