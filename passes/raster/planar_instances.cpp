#include "passes/raster/planar_instances.h"

#include <algorithm>
#include <cfloat>

namespace diptych {

std::vector<PlanarInstance> findPlanarInstances(const WorldGeometry& world,
                                                const std::function<bool(const WorldMesh&)>& keep) {
  std::vector<PlanarInstance> planes;
  for (const WorldMesh& mesh : world.meshes) {
    if (mesh.indices.empty() || !keep(mesh)) continue;
    vec3 best(0.f);  // cross product of the largest triangle: the best-conditioned normal
    vec3 anchor(0.f);
    Aabb box;
    float magnitude = 0.f;
    for (const vec3& p : mesh.positions) {
      box.extend(p);
      magnitude = std::max({magnitude, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const vec3 p0 = mesh.positions[mesh.indices[t]];
      const vec3 c = glm::cross(mesh.positions[mesh.indices[t + 1]] - p0,
                                mesh.positions[mesh.indices[t + 2]] - p0);
      if (glm::dot(c, c) > glm::dot(best, best)) best = c, anchor = p0;
    }
    if (!(glm::dot(best, best) > 0.f)) continue;
    const vec3 n = glm::normalize(best);
    const float d = -glm::dot(n, anchor);
    const float tolerance = 64.f * FLT_EPSILON * (magnitude + glm::length(box.hi - box.lo));
    bool planar = true;
    for (const vec3& p : mesh.positions)
      planar = planar && std::abs(glm::dot(n, p) + d) <= tolerance;
    if (planar) planes.push_back({mesh.instance, n, d, tolerance});
  }
  return planes;
}

}  // namespace diptych
