#pragma once
// The two words an analytic hit record carries (ShapeHit::record, SurfaceHit's u and v, a G-buffer
// texel lifted by liftToAnalytic), from which every consumer rebuilds the point and normal.
//
// Sphere: the octahedral encoding of the object-space unit normal n (Cigolle et al. 2014, "A
// Survey of Efficient Representations for Independent Unit Vectors", JCGT 3(2), the "oct"
// map): the point is r n, so neither the hit (two atan2 and a hypot before) nor the point (two
// sincos before) costs a trigonometric call; the texture (u, v), the spherical parameters of n,
// is computed only where it is read (materialReadsUv, ray cones, alpha masks). In float the
// encoding's angular error is under 2e-7 rad, below the 3.7e-7 of u = phi / 2 pi rounded to
// float (the record before).
// Cylinder and cone walls: (diamond angle of the point's direction about the axis, the height
// fraction v): the same idea in 2D, one float for the direction, so again no atan2 per hit and
// no sincos per point. Disc and caps: their uv (planar, no trigonometry).
#include "engine/scene/world_geometry.h"

namespace diptych {

// Octahedral map of a nonzero vector (need not be unit) to [-1, 1]^2, rounded to float, and its
// inverse, normalised in double. The fold uses sign-not-zero, so -z round-trips.
vec2 octahedralEncode(const dvec3& v);
dvec3 octahedralDecode(vec2 e);

// The 2D octahedral ("diamond") map of (x, z), not both 0 ((0, 0) gives +x), to [-2, 2], and its
// inverse, unit in double. Near +-2 a float's step is 2.4e-7, about 3.7e-7 rad of angle.
float diamondEncode(double x, double z);
dvec2 diamondDecode(float d);

// The record of an object-space point p on part (p as the intersection computed it, o + t d).
vec2 shapeHitRecord(const AnalyticShape& s, int part, const dvec3& p);
// The object-space point and unit outward normal of a record.
void shapeHitPointAndNormal(const AnalyticShape& s, int part, vec2 record, dvec3& point,
                            dvec3& normal);
// The record's texture coordinates (the tessellation's uv: shapeUv of its point).
vec2 shapeHitUv(const AnalyticShape& s, int part, vec2 record);

// The same for a placed quadric (not an SDF object): world point and unit outward normal
// ((M^-1)^T n), rounded once from double, as analyticPositionAndNormal does from a uv.
void analyticHitPointAndNormal(const AnalyticInstance& a, int part, vec2 record, vec3& position,
                               vec3& normal);
vec3 analyticHitNormal(const AnalyticInstance& a, int part, vec2 record);
// The record's texture uv; (0, 0) on SDF objects, as their polygonisation's.
vec2 analyticHitUv(const AnalyticInstance& a, int part, vec2 record);

// One quadric part's closest hit of the float world ray o + t d with float(t) in [tmin, tmax]:
// t (NaN: none) and its record. intersectAnalyticPart's arithmetic (it calls this), in 16 bytes
// that come back in two registers: Embree's callback used to copy a std::optional<ShapeHit>
// through three stack frames, store-forwarding stalls that were half of intersectAnalyticPart's
// samples (perf annotate, issue 14).
struct PartHit {
  double t;
  vec2 record;
};
PartHit analyticPartHit(const AnalyticInstance& a, int part, const vec3& o, const vec3& d,
                        float tmin, float tmax);

// Whether anything of the material depends on uv: a checker, a texture resolveMaterial reads, a
// normal map or a bump map. Otherwise resolveMaterial (engine/rt/surface_point.h) returns the
// same at every uv, and a sphere hit's uv need not be computed.
bool materialReadsUv(const Material& m);

}  // namespace diptych
