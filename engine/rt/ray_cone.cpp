#include "engine/rt/ray_cone.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/scene/analytic_hit.h"

namespace diptych {
namespace {

constexpr float kNoLod = -std::numeric_limits<float>::infinity();

// The texture uv of an analytic hit from its record, not SurfacePoint::uv (which a sphere
// leaves (0, 0) when its material reads no uv, surface_point.h).
vec2 hitUv(const WorldMesh& mesh, const SurfacePoint& p) {
  return analyticHitUv(*mesh.analytic, int(p.hit.primitive), vec2(p.hit.u, p.hit.v));
}

// World and uv (doubled) areas of the surface element at p: the triangle's, or for an analytic
// part the parallelogram of its uv partial derivatives (finite differences of the exact map).
bool elementAreas(const WorldGeometry& world, const SurfacePoint& p, float& worldArea,
                  float& uvArea) {
  const WorldMesh& mesh = world.meshes[std::size_t(p.hit.instance)];
  if (p.hit.analytic) {
    if (!mesh.analytic || mesh.analytic->sdf) return false;
    const float h = 1e-3f;
    const int part = int(p.hit.primitive);
    const vec2 uv = hitUv(mesh, p);
    const vec3 du = analyticPosition(*mesh.analytic, part, uv + vec2(h, 0.f)) -
                    analyticPosition(*mesh.analytic, part, uv - vec2(h, 0.f));
    const vec3 dv = analyticPosition(*mesh.analytic, part, uv + vec2(0.f, h)) -
                    analyticPosition(*mesh.analytic, part, uv - vec2(0.f, h));
    worldArea = glm::length(glm::cross(du, dv));
    uvArea = 4.f * h * h;
    return worldArea > 0.f;
  }
  if (mesh.uvs.empty()) return false;
  const std::uint32_t* tri = &mesh.indices[3 * std::size_t(p.hit.primitive)];
  const vec3 e1 = mesh.positions[tri[1]] - mesh.positions[tri[0]];
  const vec3 e2 = mesh.positions[tri[2]] - mesh.positions[tri[0]];
  const vec2 t1 = mesh.uvs[tri[1]] - mesh.uvs[tri[0]], t2 = mesh.uvs[tri[2]] - mesh.uvs[tri[0]];
  worldArea = glm::length(glm::cross(e1, e2));
  uvArea = std::fabs(t1.x * t2.y - t1.y * t2.x);
  return worldArea > 0.f && uvArea > 0.f;
}

}  // namespace

float pixelSpreadAngle(const Camera& camera, int height) {
  return std::atan(2.f * std::tan(0.5f * camera.verticalFov) / float(std::max(1, height)));
}

float coneUvLod(const WorldGeometry& world, const SurfacePoint& p, const vec3& direction,
                float width) {
  float worldArea = 0.f, uvArea = 0.f;
  if (!(width > 0.f) || !elementAreas(world, p, worldArea, uvArea)) return kNoLod;
  const float cosine = std::fabs(glm::dot(p.geometricNormal, glm::normalize(direction)));
  // Grazing hits would send lambda to infinity; the chain's top level is reached long before.
  const float delta0 = 0.5f * std::log2(uvArea / worldArea);
  return delta0 + std::log2(width) - std::log2(std::max(cosine, 1e-4f));
}

float surfaceCurvature(const WorldGeometry& world, const SurfacePoint& p) {
  if (p.hit.instance < 0 || p.hit.instance >= int(world.meshes.size())) return 0.f;
  const WorldMesh& mesh = world.meshes[std::size_t(p.hit.instance)];
  if (p.hit.analytic) {
    if (!mesh.analytic || mesh.analytic->sdf) return 0.f;
    const float h = 1e-3f;
    const int part = int(p.hit.primitive);
    const vec2 uv = hitUv(mesh, p);
    float k = 0.f;
    for (const vec2 step : {vec2(h, 0.f), vec2(0.f, h)}) {
      vec3 p0, n0, p1, n1;  // bit for bit analyticPosition's and analyticNormal's
      analyticPositionAndNormal(*mesh.analytic, part, uv + step, p1, n1);
      analyticPositionAndNormal(*mesh.analytic, part, uv - step, p0, n0);
      const vec3 dp = p1 - p0, dn = n1 - n0;
      const float len = glm::length(dp);
      if (len > 0.f) k = std::max(k, glm::length(dn) / len);
    }
    return k;
  }
  if (mesh.normals.empty()) return 0.f;
  const std::uint32_t* tri = &mesh.indices[3 * std::size_t(p.hit.primitive)];
  float k = 0.f;
  for (int e = 0; e < 3; ++e) {
    const std::uint32_t a = tri[e], b = tri[(e + 1) % 3];
    const float len = glm::length(mesh.positions[b] - mesh.positions[a]);
    if (len > 0.f) k = std::max(k, glm::length(mesh.normals[b] - mesh.normals[a]) / len);
  }
  return k;
}

RayCone reflectedCone(const WorldGeometry& world, const SurfacePoint& p, float width,
                      float spread) {
  return {width, spread + 2.f * surfaceCurvature(world, p) * width};
}

}  // namespace diptych
