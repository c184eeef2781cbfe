#include "engine/scene/world_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include "engine/scene/analytic_hit.h"
#include "engine/scene/analytic_tangents.h"
#include "engine/scene/sdf.h"

namespace diptych {
namespace {

// Area-weighted vertex normals (the cross product's length is twice the triangle area).
std::vector<vec3> computeVertexNormals(const std::vector<vec3>& p,
                                       const std::vector<std::uint32_t>& idx) {
  std::vector<vec3> n(p.size(), vec3(0.f));
  for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
    const vec3 face = glm::cross(p[idx[t + 1]] - p[idx[t]], p[idx[t + 2]] - p[idx[t]]);
    for (int k = 0; k < 3; ++k) n[idx[t + k]] += face;
  }
  for (vec3& v : n) {
    const float len = glm::length(v);
    v = len > 0.f && std::isfinite(len) ? v / len : vec3(0.f, 1.f, 0.f);
  }
  return n;
}

AnalyticInstance placeShape(const AnalyticShape& shape, std::shared_ptr<const SdfObject> sdf,
                            const mat4& transform) {
  AnalyticInstance a;
  a.shape = shape;
  a.sdf = std::move(sdf);
  a.toWorld = dmat4(transform);
  a.toObject = glm::inverse(a.toWorld);
  dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (int part = 0; part < analyticPartCount(a); ++part) {
    dvec3 plo, phi;
    analyticPartWorldBounds(a, part, plo, phi);
    lo = glm::min(lo, plo);
    hi = glm::max(hi, phi);
  }
  // Rounded outward so the float box contains the double one.
  constexpr float kInf = std::numeric_limits<float>::infinity();
  for (int i = 0; i < 3; ++i) {
    a.bounds.lo[i] = std::nextafter(float(lo[i]), -kInf);
    a.bounds.hi[i] = std::nextafter(float(hi[i]), kInf);
  }
  a.magnitude = glm::max(glm::abs(a.bounds.lo), glm::abs(a.bounds.hi));
  return a;
}

// Sphere tracing inside the object's box: the ray is clipped to it by the slab test, so the
// tracer never marches through empty space outside, and each ray's steps are recorded. The box
// is padded by 4 tolerances: a box face can touch the surface (a cube, the sponge), and a ray
// entering there must not start within 2 tolerances of it, where the tracer would take it for a
// ray leaving the surface (sphereTrace).
std::optional<ShapeHit> intersectSdf(const SdfObject& s, const dvec3& o, const dvec3& d, float tmin,
                                     float tmax, SdfStats* stats) {
  double t0 = tmin, t1 = tmax;
  const double pad = 4.0 * s.settings.tolerance;
  for (int i = 0; i < 3; ++i) {
    const double inv = 1.0 / d[i];
    double a = (s.lo[i] - pad - o[i]) * inv, b = (s.hi[i] + pad - o[i]) * inv;
    if (a > b) std::swap(a, b);
    if (!std::isnan(a)) t0 = std::max(t0, a);
    if (!std::isnan(b)) t1 = std::min(t1, b);
  }
  if (!(t0 <= t1)) return std::nullopt;
  const SphereTraceResult r = sphereTrace(s.sdf, o, d, t0, t1, s.settings);
  if (stats) stats->record(r);
  if (!r.t || float(*r.t) < tmin || float(*r.t) > tmax) return std::nullopt;
  const dvec3 p = o + *r.t * d;
  return ShapeHit{*r.t, 0, vec2(float(p.x), float(p.y)), p};
}

}  // namespace

std::vector<vec4> computeVertexTangents(const std::vector<vec3>& p, const std::vector<vec3>& n,
                                        const std::vector<vec2>& uv,
                                        const std::vector<std::uint32_t>& idx) {
  std::vector<vec3> tSum(p.size(), vec3(0.f)), bSum(p.size(), vec3(0.f));
  for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
    const std::uint32_t a = idx[t], b = idx[t + 1], c = idx[t + 2];
    const vec3 e1 = p[b] - p[a], e2 = p[c] - p[a];
    const vec2 d1 = uv[b] - uv[a], d2 = uv[c] - uv[a];
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (!(std::abs(det) > 0.f) || !std::isfinite(det)) continue;  // degenerate uv triangle
    const float r = 1.f / det;
    const vec3 dPdu = (e1 * d2.y - e2 * d1.y) * r;
    const vec3 dPdv = (e2 * d1.x - e1 * d2.x) * r;
    for (std::uint32_t k : {a, b, c}) {
      tSum[k] += dPdu;
      bSum[k] -= dPdv;  // image-up bitangent (see the header)
    }
  }
  std::vector<vec4> out(p.size(), vec4(0.f, 0.f, 0.f, 1.f));
  for (std::size_t i = 0; i < p.size(); ++i) {
    vec3 t = tSum[i] - n[i] * glm::dot(n[i], tSum[i]);
    const float len = glm::length(t);
    if (!(len > 0.f) || !std::isfinite(len)) continue;  // no uv gradient: left as zero
    t /= len;
    out[i] = vec4(t, glm::dot(glm::cross(n[i], t), bSum[i]) < 0.f ? -1.f : 1.f);
  }
  return out;
}

int analyticPartCount(const AnalyticInstance& a) {
  return a.sdf ? 1 : partCount(a.shape);
}

void analyticPartBounds(const AnalyticInstance& a, int part, dvec3& lo, dvec3& hi) {
  if (a.sdf) {  // with intersectSdf's padding
    lo = a.sdf->lo - 4.0 * a.sdf->settings.tolerance;
    hi = a.sdf->hi + 4.0 * a.sdf->settings.tolerance;
    return;
  }
  partBounds(a.shape, part, lo, hi);
}

void analyticPartWorldBounds(const AnalyticInstance& a, int part, dvec3& lo, dvec3& hi) {
  dvec3 plo, phi;
  analyticPartBounds(a, part, plo, phi);
  lo = dvec3(std::numeric_limits<double>::max());
  hi = dvec3(-std::numeric_limits<double>::max());
  for (int corner = 0; corner < 8; ++corner) {
    const dvec3 c((corner & 1) ? phi.x : plo.x, (corner & 2) ? phi.y : plo.y,
                  (corner & 4) ? phi.z : plo.z);
    const dvec3 w = dvec3(a.toWorld * glm::dvec4(c, 1.0));
    lo = glm::min(lo, w);
    hi = glm::max(hi, w);
  }
}

vec3 sdfNormal(const AnalyticInstance& a, const dvec3& p) {
  const dvec3 n = sdfNormal(a.sdf->sdf, p, a.sdf->settings.tolerance);
  return toWorldNormal(a, n);
}

std::optional<ShapeHit> intersectAnalyticPart(const AnalyticInstance& a, int part, const vec3& o,
                                              const vec3& d, float tmin, float tmax,
                                              SdfStats* stats) {
  // One part (Embree's callback, or a lift onto a sphere or disc, whose closest hit over all
  // parts is its one part's): the callback's arithmetic, in registers (analytic_hit.h).
  if (!a.sdf && (part >= 0 || partCount(a.shape) == 1)) {
    const PartHit h = analyticPartHit(a, std::max(part, 0), o, d, tmin, tmax);
    if (std::isnan(h.t)) return std::nullopt;
    return ShapeHit{h.t, std::max(part, 0), h.record};
  }
  const ObjectRay r = toObjectRay(a, o, d);
  if (a.sdf) return intersectSdf(*a.sdf, r.origin, r.direction, tmin, tmax, stats);
  auto hit = intersectShape(a.shape, r.origin, r.direction, double(tmin), double(tmax));
  if (hit && !(float(hit->t) >= tmin && float(hit->t) <= tmax)) return std::nullopt;
  return hit;
}

bool analyticPartOccludes(const AnalyticInstance& a, int part, const vec3& o, const vec3& d,
                          float tmin, float tmax, SdfStats* stats) {
  if (a.sdf) return intersectAnalyticPart(a, part, o, d, tmin, tmax, stats).has_value();
  // The same arithmetic as intersectAnalyticPart, so both agree on every ray.
  const ObjectRay r = toObjectRay(a, o, d);
  const double t = partDistance(a.shape, part, r.origin, r.direction, double(tmin), double(tmax));
  return !std::isnan(t) && float(t) >= tmin && float(t) <= tmax;
}

std::optional<ShapeHit> intersectAnalytic(const AnalyticInstance& a, const vec3& o, const vec3& d,
                                          float tmin, float tmax) {
  return intersectAnalyticPart(a, -1, o, d, tmin, tmax);
}

vec3 analyticPosition(const AnalyticInstance& a, int part, vec2 uv) {
  return toWorldPoint(a, shapePoint(a.shape, part, uv));
}

vec3 analyticNormal(const AnalyticInstance& a, int part, vec2 uv) {
  return toWorldNormal(a, shapeNormal(a.shape, part, uv));
}

void analyticPositionAndNormal(const AnalyticInstance& a, int part, vec2 uv, vec3& position,
                               vec3& normal) {
  dvec3 p, n;
  shapePointAndNormal(a.shape, part, uv, p, n);
  position = toWorldPoint(a, p);
  normal = toWorldNormal(a, n);
}

void analyticTangents(const AnalyticInstance& a, int part, vec2 uv, vec3& tu, vec3& tv) {
  dvec3 du, dv;
  shapeDerivatives(a.shape, part, uv, du, dv);
  const glm::dmat3 linear(a.toWorld);
  tu = vec3(linear * du);
  tv = vec3(linear * dv);
}

std::size_t WorldGeometry::triangleCount() const {
  std::size_t n = 0;
  for (const WorldMesh& m : meshes) n += m.indices.size() / 3;
  return n;
}

namespace {
vec3 computeFaceNormal(const WorldMesh& m, std::uint32_t prim) {
  const std::uint32_t* t = &m.indices[3 * std::size_t(prim)];
  const vec3 n =
      glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
  const float len = glm::length(n);
  return len > 0.f ? n / len : vec3(0.f, 1.f, 0.f);
}
}  // namespace

WorldGeometry flattenScene(const Scene& scene) {
  WorldGeometry world;
  world.meshes.reserve(scene.instances.size());
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& inst = scene.instances[i];
    const Mesh& mesh = scene.meshes[inst.mesh];
    WorldMesh w;
    w.instance = int(i);
    w.material = mesh.material;
    w.mirrored = glm::determinant(mat3(inst.transform)) < 0.f;
    w.motion = inst.motion;
    w.positions.reserve(mesh.positions.size());
    for (const vec3& p : mesh.positions) w.positions.push_back(vec3(inst.transform * vec4(p, 1.f)));
    w.indices = mesh.indices;
    if (w.mirrored) {
      for (std::size_t t = 0; t + 2 < w.indices.size(); t += 3)
        std::swap(w.indices[t + 1], w.indices[t + 2]);
    }
    if (mesh.normals.size() == mesh.positions.size()) {
      const mat3 normalMatrix = glm::transpose(glm::inverse(mat3(inst.transform)));
      w.normals.reserve(mesh.normals.size());
      for (const vec3& n : mesh.normals) {
        const vec3 t = normalMatrix * n;
        const float len = glm::length(t);
        w.normals.push_back(len > 0.f && std::isfinite(len) ? t / len : vec3(0.f, 1.f, 0.f));
      }
    } else {
      w.normals = computeVertexNormals(w.positions, w.indices);
    }
    if (mesh.uvs.size() == mesh.positions.size()) w.uvs = mesh.uvs;
    if (scene.material(mesh.material).normalTexture >= 0 && !w.uvs.empty()) {
      if (mesh.tangents.size() == mesh.positions.size()) {
        const mat3 linear(inst.transform);
        w.tangents.reserve(mesh.tangents.size());
        for (const vec4& t : mesh.tangents) {
          const vec3 moved = linear * vec3(t);
          const float len = glm::length(moved);
          // A mirroring transform turns the handedness of the frame over.
          const float sign = (t.w < 0.f ? -1.f : 1.f) * (w.mirrored ? -1.f : 1.f);
          w.tangents.push_back(
              vec4(len > 0.f && std::isfinite(len) ? moved / len : vec3(0.f), sign));
        }
      } else {
        w.tangents = computeVertexTangents(w.positions, w.normals, w.uvs, w.indices);
      }
    }
    w.faceNormals.resize(w.indices.size() / 3);
    for (std::size_t t = 0; t < w.faceNormals.size(); ++t)
      w.faceNormals[t] = computeFaceNormal(w, std::uint32_t(t));
    for (const vec3& p : w.positions) world.bounds.extend(p);
    if (mesh.analytic || mesh.sdf) {
      w.analytic = placeShape(mesh.analytic.value_or(AnalyticShape{}), mesh.sdf, inst.transform);
      world.bounds.extend(w.analytic->bounds);
    }
    world.meshes.push_back(std::move(w));
  }
  return world;
}

vec3 interpolatePosition(const WorldMesh& m, std::uint32_t prim, float u, float v) {
  const std::uint32_t* t = &m.indices[3 * std::size_t(prim)];
  return (1.f - u - v) * m.positions[t[0]] + u * m.positions[t[1]] + v * m.positions[t[2]];
}

vec3 interpolateNormal(const WorldMesh& m, std::uint32_t prim, float u, float v) {
  const std::uint32_t* t = &m.indices[3 * std::size_t(prim)];
  const vec3 n = (1.f - u - v) * m.normals[t[0]] + u * m.normals[t[1]] + v * m.normals[t[2]];
  const float len = glm::length(n);
  return len > 0.f ? n / len : geometricNormal(m, prim);
}

vec2 interpolateUv(const WorldMesh& m, std::uint32_t prim, float u, float v) {
  if (m.uvs.empty()) return vec2(u, v);
  const std::uint32_t* t = &m.indices[3 * std::size_t(prim)];
  return (1.f - u - v) * m.uvs[t[0]] + u * m.uvs[t[1]] + v * m.uvs[t[2]];
}

vec3 geometricNormal(const WorldMesh& m, std::uint32_t prim) {
  if (std::size_t(prim) < m.faceNormals.size()) return m.faceNormals[prim];
  return computeFaceNormal(m, prim);
}

vec4 interpolateTangent(const WorldMesh& m, std::uint32_t prim, float u, float v) {
  if (m.tangents.empty()) return vec4(0.f, 0.f, 0.f, 1.f);
  const std::uint32_t* t = &m.indices[3 * std::size_t(prim)];
  const vec3 xyz = (1.f - u - v) * vec3(m.tangents[t[0]]) + u * vec3(m.tangents[t[1]]) +
                   v * vec3(m.tangents[t[2]]);
  return vec4(xyz, m.tangents[t[0]].w);
}

}  // namespace diptych
