#include "engine/scene/analytic_hit.h"

#include <cmath>
#include <limits>

namespace diptych {
namespace {

bool octahedralRecord(const AnalyticShape& s) {
  return s.type == ShapeType::Sphere;
}

double signNotZero(double x) {
  return std::copysign(1.0, x);
}

}  // namespace

vec2 octahedralEncode(const dvec3& v) {
  // Project onto the octahedron |x| + |y| + |z| = 1, then fold the lower half (z < 0) over the
  // diagonals (Cigolle et al. 2014, listing 1).
  const double l1 = std::abs(v.x) + std::abs(v.y) + std::abs(v.z);
  double x = v.x / l1, y = v.y / l1;
  if (v.z < 0.0) {
    const double fx = (1.0 - std::abs(y)) * signNotZero(x);
    y = (1.0 - std::abs(x)) * signNotZero(y);
    x = fx;
  }
  return vec2(float(x), float(y));
}

dvec3 octahedralDecode(vec2 e) {
  const double x = e.x, y = e.y;
  dvec3 v(x, y, 1.0 - std::abs(x) - std::abs(y));
  if (v.z < 0.0) {
    v.x = (1.0 - std::abs(y)) * signNotZero(x);
    v.y = (1.0 - std::abs(x)) * signNotZero(y);
  }
  return glm::normalize(v);
}

vec2 shapeHitParams(const AnalyticShape& s, int part, const dvec3& p) {
  return octahedralRecord(s) ? octahedralEncode(p) : shapeUv(s, part, p);
}

void shapeHitPointAndNormal(const AnalyticShape& s, int part, vec2 params, dvec3& point,
                            dvec3& normal) {
  if (!octahedralRecord(s)) return shapePointAndNormal(s, part, params, point, normal);
  normal = octahedralDecode(params);  // grad(x^2+y^2+z^2-r^2) / 2 = p = r n
  point = double(s.radius) * normal;
}

vec2 shapeHitUv(const AnalyticShape& s, int part, vec2 params) {
  return octahedralRecord(s) ? shapeUv(s, part, octahedralDecode(params)) : params;
}

void analyticHitPointAndNormal(const AnalyticInstance& a, int part, vec2 params, vec3& position,
                               vec3& normal) {
  dvec3 p, n;
  shapeHitPointAndNormal(a.shape, part, params, p, n);
  position = vec3(dvec3(a.toWorld * glm::dvec4(p, 1.0)));
  normal = vec3(glm::normalize(glm::transpose(glm::dmat3(a.toObject)) * n));
}

vec3 analyticHitNormal(const AnalyticInstance& a, int part, vec2 params) {
  vec3 position, normal;
  analyticHitPointAndNormal(a, part, params, position, normal);
  return normal;
}

vec2 analyticHitUv(const AnalyticInstance& a, int part, vec2 params) {
  return a.sdf ? vec2(0.f) : shapeHitUv(a.shape, part, params);
}

PartHit analyticPartHit(const AnalyticInstance& a, int part, const vec3& o, const vec3& d,
                        float tmin, float tmax) {
  // An affine map keeps t: object-space o' + t d' is the image of o + t d.
  const dvec3 oo = dvec3(a.toObject * glm::dvec4(dvec3(o), 1.0));
  const dvec3 od = dvec3(a.toObject * glm::dvec4(dvec3(d), 0.0));
  const double t = partDistance(a.shape, part, oo, od, double(tmin), double(tmax));
  if (std::isnan(t) || !(float(t) >= tmin && float(t) <= tmax))
    return {std::numeric_limits<double>::quiet_NaN(), vec2(0.f)};
  return {t, shapeHitParams(a.shape, part, oo + t * od)};
}

bool materialReadsUv(const Material& m) {
  return m.checker || m.colorTexture >= 0 || m.emissionTexture >= 0 ||
         m.metallicRoughnessTexture >= 0 || m.occlusionTexture >= 0 || m.normalTexture >= 0 ||
         m.bump;
}

}  // namespace diptych
