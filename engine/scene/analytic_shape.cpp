#include "engine/scene/analytic_shape.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "engine/scene/analytic_hit.h"
#include "engine/scene/analytic_tangents.h"

namespace diptych {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The tessellation's angle convention (primitives.cpp, around()): phi turns counter-clockwise
// seen from +y, direction (cos phi, 0, -sin phi), u = phi / 2 pi in [0, 1).
double phiOf(double x, double z) {
  double phi = std::atan2(-z, x);
  return phi < 0.0 ? phi + kTwoPi : phi;
}

dvec3 around(double phi) {
  return dvec3(std::cos(phi), 0.0, -std::sin(phi));
}

// b*b - a*c without the cancellation of the naive form when b*b ~ a*c (Kahan's difference of
// products with one fused multiply-add; error within 1.5 ulp).
double discriminant(double a, double b, double c) {
  const double ac = a * c;
  const double err = std::fma(-a, c, ac);  // ac - a*c exactly
  return std::fma(b, b, -ac) + err;
}

// Roots of a t^2 + 2 b t + c = 0 given disc = b^2 - a c >= 0, by the stable form
// q = -(b + sign(b) sqrt(disc)), t = c / q and q / a (Ray Tracing Gems ch. 7: no subtraction of
// nearly equal numbers). Returns the smaller root first.
void stableRoots(double a, double b, double c, double disc, double& t0, double& t1) {
  const double q = -(b + std::copysign(std::sqrt(disc), b));
  if (q == 0.0) {  // b == 0 and disc == 0: a double root at c / ... = 0
    t0 = t1 = 0.0;
    return;
  }
  t0 = c / q;
  t1 = q / a;
  if (t0 > t1) std::swap(t0, t1);
}

// The helpers below return the hit distance, or kMiss (NaN) when there is none: a plain double
// stays in a register, where std::optional<double> went through the stack between the
// inlined helpers (a store-forwarding stall per call in perf annotate, issue 14).
constexpr double kMiss = std::numeric_limits<double>::quiet_NaN();

// The first of the roots in (tmin, tmax) whose point passes `accept`.
template <class Accept>
double firstRoot(double t0, double t1, double tmin, double tmax, Accept accept) {
  if (t0 > tmin && t0 < tmax && accept(t0)) return t0;
  if (t1 > tmin && t1 < tmax && accept(t1)) return t1;
  return kMiss;
}

double planeHit(double y0, double radius, const dvec3& o, const dvec3& d, double tmin,
                double tmax) {
  if (d.y == 0.0) return kMiss;
  const double t = (y0 - o.y) / d.y;
  if (!(t > tmin && t < tmax)) return kMiss;
  const double x = o.x + t * d.x, z = o.z + t * d.z;
  if (x * x + z * z > radius * radius) return kMiss;
  return t;
}

double sphereHit(double r, const dvec3& o, const dvec3& d, double tmin, double tmax) {
  // a t^2 + 2 b t + c with f = o (centre at the origin). Discriminant in the form of RTG ch. 7,
  // b^2 - a c = a (r^2 - |f - (b/a) d|^2): the squared distance of the centre from the ray is
  // computed directly instead of as the difference of two large numbers. As RTG writes it, with
  // |l|^2 = dot(l, l) and no square root (a (r - |l|)(r + |l|) before: one sqrt more on the
  // hit's dependency chain, for an error of the same order, ~1 ulp of r^2).
  const double a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - r * r;
  if (a == 0.0) return kMiss;
  // A clear miss is told by the naive b^2 - a c, without the division and square root below:
  // its rounding error is a few ulps of the terms' magnitude m, so below -1e-9 m the exact
  // discriminant, and the careful one below, are negative too. Most candidate rays (Embree
  // calls this for every ray entering the sphere's box) end here; a NaN or inf compares false
  // and takes the careful path. The result is the careful path's, bit for bit.
  const double bb = b * b, ac = a * c;
  if (bb - ac < -1e-9 * (bb + std::abs(ac) + a * r * r)) return kMiss;
  const dvec3 l = o - (b / a) * d;
  const double disc = a * (r * r - glm::dot(l, l));
  if (disc < 0.0) return kMiss;
  double t0, t1;
  stableRoots(a, b, c, disc, t0, t1);
  return firstRoot(t0, t1, tmin, tmax, [](double) { return true; });
}

double cylinderHit(double r, double h, const dvec3& o, const dvec3& d, double tmin, double tmax) {
  // x^2 + z^2 = r^2 in the xz projection, as the sphere in 2D.
  const dvec2 o2(o.x, o.z), d2(d.x, d.z);
  const double a = glm::dot(d2, d2), b = glm::dot(o2, d2), c = glm::dot(o2, o2) - r * r;
  if (a == 0.0) return kMiss;  // along the axis: never meets the side
  const dvec2 l = o2 - (b / a) * d2;
  const double disc = a * (r * r - glm::dot(l, l));
  if (disc < 0.0) return kMiss;
  double t0, t1;
  stableRoots(a, b, c, disc, t0, t1);
  return firstRoot(t0, t1, tmin, tmax, [&](double t) {
    const double y = o.y + t * d.y;
    return y >= -0.5 * h && y <= 0.5 * h;
  });
}

double coneHit(double r, double h, const dvec3& o, const dvec3& d, double tmin, double tmax) {
  // F = x^2 + z^2 - k^2 s^2 with k = r / h and s = h/2 - y (depth below the apex), s in [0, h].
  const double k2 = (r / h) * (r / h), s0 = 0.5 * h - o.y;
  const double a = d.x * d.x + d.z * d.z - k2 * d.y * d.y;
  const double b = o.x * d.x + o.z * d.z + k2 * s0 * d.y;
  const double c = o.x * o.x + o.z * o.z - k2 * s0 * s0;
  auto inside = [&](double t) {
    const double s = s0 - t * d.y;
    return s >= 0.0 && s <= h;
  };
  if (a == 0.0) {  // parallel to a generator line: one root
    if (b == 0.0) return kMiss;
    const double t = -c / (2.0 * b);
    return firstRoot(t, t, tmin, tmax, inside);
  }
  const double disc = discriminant(a, b, c);
  if (disc < 0.0) return kMiss;
  double t0, t1;
  stableRoots(a, b, c, disc, t0, t1);
  return firstRoot(t0, t1, tmin, tmax, inside);
}

}  // namespace

int partCount(const AnalyticShape& s) {
  switch (s.type) {
    case ShapeType::Sphere:
    case ShapeType::Disc:
      return 1;
    case ShapeType::Cylinder:
      return s.capped ? 3 : 1;
    case ShapeType::Cone:
      return s.capped ? 2 : 1;
  }
  return 1;
}

void partBounds(const AnalyticShape& s, int part, dvec3& lo, dvec3& hi) {
  const double r = s.radius, h2 = 0.5 * double(s.height);
  switch (s.type) {
    case ShapeType::Sphere:
      lo = dvec3(-r);
      hi = dvec3(r);
      return;
    case ShapeType::Disc:
      lo = dvec3(-r, 0.0, -r);
      hi = dvec3(r, 0.0, r);
      return;
    case ShapeType::Cylinder:
    case ShapeType::Cone: {
      const bool top = s.type == ShapeType::Cylinder && part == 1;
      const bool bottom =
          (s.type == ShapeType::Cylinder && part == 2) || (s.type == ShapeType::Cone && part == 1);
      lo = dvec3(-r, top ? h2 : -h2, -r);
      hi = dvec3(r, bottom ? -h2 : h2, r);
      return;
    }
  }
}

double partDistance(const AnalyticShape& s, int part, const dvec3& o, const dvec3& d, double tmin,
                    double tmax) {
  const double r = s.radius, h = s.height;
  double t = kMiss;
  switch (s.type) {
    case ShapeType::Sphere:
      t = sphereHit(r, o, d, tmin, tmax);
      break;
    case ShapeType::Disc:
      t = planeHit(0.0, r, o, d, tmin, tmax);
      break;
    case ShapeType::Cylinder:
      t = part == 0   ? cylinderHit(r, h, o, d, tmin, tmax)
          : part == 1 ? planeHit(0.5 * h, r, o, d, tmin, tmax)
                      : planeHit(-0.5 * h, r, o, d, tmin, tmax);
      break;
    case ShapeType::Cone:
      t = part == 0 ? coneHit(r, h, o, d, tmin, tmax) : planeHit(-0.5 * h, r, o, d, tmin, tmax);
      break;
  }
  return t;  // every helper's roots compare > tmin: a hit is never NaN
}

std::optional<double> intersectPartDistance(const AnalyticShape& s, int part, const dvec3& o,
                                            const dvec3& d, double tmin, double tmax) {
  const double t = partDistance(s, part, o, d, tmin, tmax);
  if (std::isnan(t)) return std::nullopt;
  return t;
}

std::optional<ShapeHit> intersectPart(const AnalyticShape& s, int part, const dvec3& o,
                                      const dvec3& d, double tmin, double tmax) {
  const double t = partDistance(s, part, o, d, tmin, tmax);
  if (std::isnan(t)) return std::nullopt;
  return ShapeHit{t, part, shapeHitRecord(s, part, o + t * d)};
}

std::optional<ShapeHit> intersectShape(const AnalyticShape& s, const dvec3& o, const dvec3& d,
                                       double tmin, double tmax) {
  std::optional<ShapeHit> best;
  for (int part = 0; part < partCount(s); ++part) {
    if (auto hit = intersectPart(s, part, o, d, tmin, tmax)) {
      best = hit;
      tmax = hit->t;
    }
  }
  return best;
}

namespace {
bool isPlanar(const AnalyticShape& s, int part) {
  return s.type == ShapeType::Disc || part > 0;
}
double planeY(const AnalyticShape& s, int part) {
  if (s.type == ShapeType::Disc) return 0.0;
  return s.type == ShapeType::Cylinder && part == 1 ? 0.5 * double(s.height)
                                                    : -0.5 * double(s.height);
}
}  // namespace

vec2 shapeUv(const AnalyticShape& s, int part, const dvec3& p) {
  const double r = s.radius, h = s.height;
  if (isPlanar(s, part))  // primitives.cpp addCap: uv = (1/2 + x / 2r, 1/2 + z / 2r)
    return vec2(float(0.5 + p.x / (2.0 * r)), float(0.5 + p.z / (2.0 * r)));
  const float u = float(phiOf(p.x, p.z) / kTwoPi);
  if (s.type == ShapeType::Sphere) {
    // theta from atan2, well conditioned at the poles where acos(y / r) is not.
    const double theta = std::atan2(std::hypot(p.x, p.z), p.y);
    return vec2(u < 1.f ? u : 0.f, float(theta / std::numbers::pi));
  }
  return vec2(u < 1.f ? u : 0.f, float((p.y + 0.5 * h) / h));
}

void shapePointAndNormal(const AnalyticShape& s, int part, vec2 uv, dvec3& point, dvec3& normal) {
  const double r = s.radius, h = s.height;
  if (isPlanar(s, part)) {
    point = dvec3((double(uv.x) - 0.5) * 2.0 * r, planeY(s, part), (double(uv.y) - 0.5) * 2.0 * r);
    const bool up = s.type == ShapeType::Disc || (s.type == ShapeType::Cylinder && part == 1);
    normal = dvec3(0.0, up ? 1.0 : -1.0, 0.0);
    return;
  }
  const dvec3 dir = around(kTwoPi * double(uv.x));
  switch (s.type) {
    case ShapeType::Sphere: {  // grad(x^2+y^2+z^2-r^2) / 2 = p
      const double theta = std::numbers::pi * double(uv.y);
      point = r * (std::sin(theta) * dir + dvec3(0.0, std::cos(theta), 0.0));
      normal = glm::normalize(point);
      return;
    }
    case ShapeType::Cylinder:  // grad(x^2+z^2-r^2) / 2 = (x, 0, z)
      point = r * dir + dvec3(0.0, (double(uv.y) - 0.5) * h, 0.0);
      normal = dir;
      return;
    default:  // cone: grad / 2 = (x, k^2 s, z) = k s (cos phi, k, -sin phi) ~ (h cos, r, -h sin)
      point = r * (1.0 - double(uv.y)) * dir + dvec3(0.0, (double(uv.y) - 0.5) * h, 0.0);
      normal = glm::normalize(h * dir + dvec3(0.0, r, 0.0));
      return;
  }
}

dvec3 shapePoint(const AnalyticShape& s, int part, vec2 uv) {
  dvec3 point, normal;
  shapePointAndNormal(s, part, uv, point, normal);
  return point;
}

dvec3 shapeNormal(const AnalyticShape& s, int part, vec2 uv) {
  dvec3 point, normal;
  shapePointAndNormal(s, part, uv, point, normal);
  return normal;
}

dvec3 shapeTangent(const AnalyticShape& s, int part, vec2 uv) {
  if (isPlanar(s, part)) return dvec3(1.0, 0.0, 0.0);
  const double phi = kTwoPi * double(uv.x);
  return dvec3(-std::sin(phi), 0.0, -std::cos(phi));  // d around(phi) / d phi
}

void shapeDerivatives(const AnalyticShape& s, int part, vec2 uv, dvec3& du, dvec3& dv) {
  const double r = s.radius, h = s.height;
  if (isPlanar(s, part)) {  // p = ((u - 1/2) 2r, y, (v - 1/2) 2r)
    du = dvec3(2.0 * r, 0.0, 0.0);
    dv = dvec3(0.0, 0.0, 2.0 * r);
    return;
  }
  const double phi = kTwoPi * double(uv.x);
  const dvec3 dir = around(phi);
  const dvec3 dDir = kTwoPi * dvec3(-std::sin(phi), 0.0, -std::cos(phi));  // d around / du
  switch (s.type) {
    case ShapeType::Sphere: {  // p = r (sin(pi v) around(2 pi u) + cos(pi v) y)
      const double theta = std::numbers::pi * double(uv.y);
      du = r * std::sin(theta) * dDir;
      dv = r * std::numbers::pi * (std::cos(theta) * dir - dvec3(0.0, std::sin(theta), 0.0));
      return;
    }
    case ShapeType::Cylinder:  // p = r around(2 pi u) + (v - 1/2) h y
      du = r * dDir;
      dv = dvec3(0.0, h, 0.0);
      return;
    default:  // cone: p = r (1 - v) around(2 pi u) + (v - 1/2) h y
      du = r * (1.0 - double(uv.y)) * dDir;
      dv = -r * dir + dvec3(0.0, h, 0.0);
      return;
  }
}

}  // namespace diptych
