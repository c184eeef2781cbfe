#pragma once
// The exact surfaces behind the tessellated quadrics of engine/scene/primitives.h (the
// lecture's ray-object problems 5.1-5.3: disc, sphere, cylinder, cone), in the same object
// space and with the same (u, v) parameterisation, so a material looks the same on the
// triangles and on the exact surface. Ray tracers intersect these (engine/rt/rt_scene.cpp
// registers them as Embree user geometry); rasterizers draw the tessellation.
//
// All arithmetic is in double: a hit is computed in object space from a float ray and rounded
// to float once, so its error is a few float ULPs whatever the transform.
#include <optional>

#include "engine/core/math.h"

namespace diptych {

using glm::dmat4;
using glm::dvec2;
using glm::dvec3;

enum class ShapeType { Sphere, Disc, Cylinder, Cone };

// Object space as in primitives.h: y is the axis; the sphere is centred on the origin, the disc
// lies in y = 0 (normal +y), the cylinder spans y in [-h/2, h/2], the cone has its base of
// radius r at y = -h/2 and its apex at y = +h/2. Radius and height are > 0 (the loaders reject
// degenerate shapes by name).
struct AnalyticShape {
  ShapeType type = ShapeType::Sphere;
  float radius = 1.f;
  float height = 1.f;  // cylinder, cone
  bool capped = true;  // cylinder: both caps; cone: the base disc
};

// Parts: 0 is the curved surface (the disc itself for a disc); a capped cylinder adds 1 = top
// cap (y = +h/2, normal +y) and 2 = bottom cap (normal -y); a capped cone adds 1 = base (-y).
int partCount(const AnalyticShape& s);

// Object-space box of one part.
void partBounds(const AnalyticShape& s, int part, dvec3& lo, dvec3& hi);

struct ShapeHit {
  double t = 0.0;
  int part = 0;
  vec2 record{0.f};  // the hit record (analytic_hit.h): on a sphere its octahedral normal
  dvec3 point{0.0};  // SDF objects: the object-space hit point (they have no parameters)
};

// Closest hit of o + t d (object space, d need not be unit) with t in (tmin, tmax) over all
// parts. Both roots of a quadric are tried, so a ray starting inside finds the far wall.
std::optional<ShapeHit> intersectShape(const AnalyticShape& s, const dvec3& o, const dvec3& d,
                                       double tmin, double tmax);
// The same restricted to one part.
std::optional<ShapeHit> intersectPart(const AnalyticShape& s, int part, const dvec3& o,
                                      const dvec3& d, double tmin, double tmax);

// intersectPart's distance alone, without the (trigonometric) surface parameters: what an
// occlusion query needs.
std::optional<double> intersectPartDistance(const AnalyticShape& s, int part, const dvec3& o,
                                            const dvec3& d, double tmin, double tmax);
// The same distance, NaN when there is none: a plain double comes back in a register, where
// std::optional<double> came back through the stack with an 8-byte load of its 1-byte flag, a
// store-forwarding stall on every call (a seventh of the function's time; perf annotate, issue
// 14). For the per-ray callers (intersectPart, analyticPartOccludes).
double partDistance(const AnalyticShape& s, int part, const dvec3& o, const dvec3& d, double tmin,
                    double tmax);

// The object-space point and unit outward normal of part at uv; the normal is the normalised
// gradient of the part's implicit function (sphere x^2+y^2+z^2-r^2, cylinder x^2+z^2-r^2, cone
// x^2+z^2-(r/h)^2 (h/2-y)^2; caps and disc: +-y), evaluated from uv (at the cone's apex, where
// the gradient vanishes, its limit along the meridian u).
dvec3 shapePoint(const AnalyticShape& s, int part, vec2 uv);
dvec3 shapeNormal(const AnalyticShape& s, int part, vec2 uv);
// Both at once, their trigonometry evaluated once (the two functions above call this).
void shapePointAndNormal(const AnalyticShape& s, int part, vec2 uv, dvec3& point, dvec3& normal);
// dp/du, the direction of increasing u, unit (the glTF tangent convention: w = +1 with the
// bitangent cross(n, t)); caps and disc: +x, as the tessellation's planar uv map.
dvec3 shapeTangent(const AnalyticShape& s, int part, vec2 uv);
// The parameters of an object-space point on part (the inverse of shapePoint).
vec2 shapeUv(const AnalyticShape& s, int part, const dvec3& p);

}  // namespace diptych
