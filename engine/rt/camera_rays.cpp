#include "engine/rt/camera_rays.h"

#include <cmath>
#include <limits>

#include "engine/scene/analytic_hit.h"

namespace diptych {

bool CameraRays::culled(const Hit& hit, const vec3& direction) const {
  const WorldMesh& mesh = world.meshes[std::size_t(hit.instance)];
  if (scene.material(mesh.material).doubleSided) return false;
  // A quadric's Hit::Ng is 0 unless the tracer asked for it (RtScene::intersect): its outward
  // normal from the hit record. SDF hits and triangles carry their Ng.
  const vec3 n = hit.analytic && mesh.analytic && !mesh.analytic->sdf
                     ? analyticHitNormal(*mesh.analytic, int(hit.primitive), vec2(hit.u, hit.v))
                     : hit.Ng;
  return glm::dot(n, direction) > 0.f;
}

bool CameraRays::intersect(const Ray& ray, Hit& hit, bool wantNormal) const {
  if (!rt.intersect(ray, 0.f, std::numeric_limits<float>::infinity(), hit, wantNormal))
    return false;
  return !culled(hit, ray.direction) || pastCulled(ray, hit, wantNormal);
}

void CameraRays::intersectRays(std::span<const Ray> rays, std::span<Hit> hits,
                               std::span<const Hit*> found, bool wantNormal) const {
  rt.intersectRays(rays, hits, found, wantNormal);
  for (std::size_t i = 0; i < rays.size(); ++i)
    if (found[i] && culled(hits[i], rays[i].direction))
      found[i] = pastCulled(rays[i], hits[i], wantNormal) ? &hits[i] : nullptr;
}

bool CameraRays::pastCulled(const Ray& ray, Hit& hit, bool wantNormal) const {
  // Each retrace starts at the next float after the culled hit (t in units of |direction|, as
  // tnear), so t strictly grows; the bound only guards against a pathological stack of back
  // faces (the ray then sees nothing, as if every one were culled).
  constexpr int kMaxCulled = 64;
  const float inf = std::numeric_limits<float>::infinity();
  for (int i = 0; i < kMaxCulled; ++i) {
    if (!rt.intersect(ray, std::nextafter(hit.t, inf), inf, hit, wantNormal)) return false;
    if (!culled(hit, ray.direction)) return true;
  }
  return false;
}

}  // namespace diptych
