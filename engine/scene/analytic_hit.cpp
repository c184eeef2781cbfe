#include "engine/scene/analytic_hit.h"

#include <cmath>
#include <limits>

namespace diptych {
namespace {

enum class Record { Octahedral, Diamond, Uv };

Record recordOf(const AnalyticShape& s, int part) {
  if (s.type == ShapeType::Sphere) return Record::Octahedral;
  if ((s.type == ShapeType::Cylinder || s.type == ShapeType::Cone) && part == 0)
    return Record::Diamond;
  return Record::Uv;
}

// The cylinder's and cone's walls: a point's direction (x, 0, z) about the axis, unit.
dvec3 wallDirection(vec2 record) {
  const dvec2 xz = diamondDecode(record.x);
  return dvec3(xz.x, 0.0, xz.y);
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

float diamondEncode(double x, double z) {
  // The 2D octahedral map: x / (|x| + |z|) in [-1, 1] on each half, the halves laid end to end
  // (z >= 0 on [0, 2], z < 0 on [-2, 0)); the axis itself (apex of a cone) gets direction +x.
  const double l1 = std::abs(x) + std::abs(z);
  if (!(l1 > 0.0)) return 0.f;
  const double p = x / l1;
  return float(z >= 0.0 ? 1.0 - p : p - 1.0);
}

dvec2 diamondDecode(float d) {
  const double x = d >= 0.f ? 1.0 - double(d) : 1.0 + double(d);
  const double z = 1.0 - std::abs(x);
  return glm::normalize(dvec2(x, d >= 0.f ? z : -z));
}

vec2 shapeHitRecord(const AnalyticShape& s, int part, const dvec3& p) {
  switch (recordOf(s, part)) {
    case Record::Octahedral:
      return octahedralEncode(p);
    case Record::Diamond:  // v: the height fraction, as the uv's
      return vec2(diamondEncode(p.x, p.z), shapeUv(s, part, p).y);
    default:
      return shapeUv(s, part, p);
  }
}

void shapeHitPointAndNormal(const AnalyticShape& s, int part, vec2 record, dvec3& point,
                            dvec3& normal) {
  const double r = s.radius, h = s.height, v = record.y;
  switch (recordOf(s, part)) {
    case Record::Octahedral:
      normal = octahedralDecode(record);  // grad(x^2+y^2+z^2-r^2) / 2 = p = r n
      point = r * normal;
      return;
    case Record::Diamond: {  // shapePointAndNormal's formulas, with dir from the record
      const dvec3 dir = wallDirection(record);
      const dvec3 y(0.0, (v - 0.5) * h, 0.0);
      if (s.type == ShapeType::Cylinder) {
        point = r * dir + y;
        normal = dir;
      } else {
        point = r * (1.0 - v) * dir + y;
        normal = glm::normalize(h * dir + dvec3(0.0, r, 0.0));
      }
      return;
    }
    default:
      shapePointAndNormal(s, part, record, point, normal);
      return;
  }
}

vec2 shapeHitUv(const AnalyticShape& s, int part, vec2 record) {
  switch (recordOf(s, part)) {
    case Record::Octahedral:
      return shapeUv(s, part, octahedralDecode(record));
    case Record::Diamond:  // shapeUv's u reads x and z alone
      return vec2(shapeUv(s, part, wallDirection(record)).x, record.y);
    default:
      return record;
  }
}

void analyticHitPointAndNormal(const AnalyticInstance& a, int part, vec2 record, vec3& position,
                               vec3& normal) {
  dvec3 p, n;
  shapeHitPointAndNormal(a.shape, part, record, p, n);
  position = toWorldPoint(a, p);
  normal = toWorldNormal(a, n);
}

vec3 analyticHitNormal(const AnalyticInstance& a, int part, vec2 record) {
  vec3 position, normal;
  analyticHitPointAndNormal(a, part, record, position, normal);
  return normal;
}

vec2 analyticHitUv(const AnalyticInstance& a, int part, vec2 record) {
  return a.sdf ? vec2(0.f) : shapeHitUv(a.shape, part, record);
}

PartHit analyticPartHit(const AnalyticInstance& a, int part, const vec3& o, const vec3& d,
                        float tmin, float tmax) {
  const ObjectRay r = toObjectRay(a, o, d);
  const double t = partDistance(a.shape, part, r.origin, r.direction, double(tmin), double(tmax));
  if (std::isnan(t) || !(float(t) >= tmin && float(t) <= tmax))
    return {std::numeric_limits<double>::quiet_NaN(), vec2(0.f)};
  return {t, shapeHitRecord(a.shape, part, r.origin + t * r.direction)};
}

bool materialReadsUv(const Material& m) {
  return m.checker || m.colorTexture >= 0 || m.emissionTexture >= 0 ||
         m.metallicRoughnessTexture >= 0 || m.occlusionTexture >= 0 || m.normalTexture >= 0 ||
         m.iridescenceTexture >= 0 || m.iridescenceThicknessTexture >= 0 || m.bump;
}

}  // namespace diptych
