#pragma once
#include <functional>
#include <vector>

#include "engine/scene/world_geometry.h"

namespace diptych {

// A scene instance whose triangles all lie on one plane: the receivers of planar_shadows and the
// mirrors of planar_mirror.
struct PlanarInstance {
  int instance = -1;
  vec3 normal{0.f};    // unit, the face normal of the largest triangle (either side may face you)
  float offset = 0.f;  // plane: dot(normal, x) + offset = 0
  // How far from the plane a vertex of the mesh may lie and still count as on it (world units).
  float tolerance = 0.f;
};

// The planar meshes among those `keep` accepts. A mesh is planar when every vertex lies within
// 64 ulp-scale units of the plane of its largest triangle: 64 FLT_EPSILON times the mesh's
// largest coordinate magnitude plus its extent (a relative tolerance: the rounding of the
// flattened world positions scales with their magnitude; no world-space epsilon).
std::vector<PlanarInstance> findPlanarInstances(const WorldGeometry& world,
                                                const std::function<bool(const WorldMesh&)>& keep);

}  // namespace diptych
