#pragma once
// Signed-distance objects (the lecture's sphere tracing, after J. C. Hart, "Sphere tracing: a
// geometric method for the antialiased ray tracing of implicit surfaces", The Visual Computer
// 12(10), 1996): primitive distance functions, CSG, transforms and one fractal, evaluated in
// double; the sphere tracer, plain and over-relaxed (Keinert, Schäfer, Korndörfer, Ganse and
// Stamminger, "Enhanced Sphere Tracing", STAG 2014); central-difference normals; and a
// surface-nets polygonisation for the rasterizer.
#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/core/math.h"
#include "engine/core/work_limit.h"
#include "engine/scene/analytic_shape.h"

namespace diptych {

enum class SdfKind {
  Sphere,        // radius
  Box,           // halfSize
  RoundBox,      // halfSize (outer), radius (rounding)
  Torus,         // radius2 (major, in the xz plane), radius (minor)
  Capsule,       // a, b, radius
  Plane,         // y = 0, normal +y (unbounded: intersect it with a bounded shape)
  Menger,        // Menger sponge in [-halfSize.x, halfSize.x]^3, `iterations` levels
  Union,         // children left, right
  Intersection,  //
  Difference,    // left minus right
  SmoothUnion,   // blend width k (Quilez's polynomial smooth minimum)
};

struct SdfNode {
  SdfKind kind = SdfKind::Sphere;
  dvec3 halfSize{1.0};
  double radius = 1.0, radius2 = 0.0, k = 0.1;
  dvec3 a{0.0}, b{0.0};
  int iterations = 3;
  int left = -1, right = -1;
  // Node transform (rigid + uniform scale s): the node's shape lives in local coordinates
  // p_local = toLocal p; its distance is s times the local distance (a uniform scale keeps a
  // distance a distance; a non-uniform one would not, so nodes take none; the instance
  // transform may, as tracing happens in the object space it maps from).
  dmat4 toLocal{1.0};
  double scale = 1.0;
};

struct Sdf {
  std::vector<SdfNode> nodes;
  int root = 0;
};

double sdfDistance(const Sdf& sdf, const dvec3& p);
// Object-space bounds of the zero set (conservative); nullopt when unbounded (a bare plane).
std::optional<std::pair<dvec3, dvec3>> sdfBounds(const Sdf& sdf);
// Central differences with step h: normalize(sum_i e_i (f(p + h e_i) - f(p - h e_i))).
dvec3 sdfNormal(const Sdf& sdf, const dvec3& p, double h);

struct SphereTraceSettings {
  double tolerance = 1e-4;  // hit when the distance falls below this (object units)
  int maxSteps = 256;       // iteration cap
  double relaxation = 1.0;  // 1: Hart's plain tracer; in (1, 2): Keinert et al.'s over-relaxation
};

struct SphereTraceResult {
  std::optional<double> t;  // hit parameter along o + t d
  int steps = 0;            // distance evaluations spent
  bool cappedOut = false;   // gave up at maxSteps (counted as a miss)
};

// Sphere tracing of o + t d over [tmin, tmax] (object space; d need not be unit). A ray that
// starts within 2 tolerances of the surface (a secondary ray leaving it) first marches off it,
// on the side its direction points to (sign of d . gradient), before hits count: the surface
// is only known to within the tolerance, far above any float offset of the origin.
SphereTraceResult sphereTrace(const Sdf& sdf, const dvec3& o, const dvec3& d, double tmin,
                              double tmax, const SphereTraceSettings& settings);

// Per-object step statistics, summed over every ray any thread traced (relaxed atomics).
struct SdfStats {
  std::atomic<std::uint64_t> rays{0}, steps{0}, capped{0};
  std::atomic<int> maxSteps{0};
  void record(const SphereTraceResult& r);  // also adds r to this thread's SdfRayTally
  void reset();
};

// The sphere-tracing work done on the calling thread since the caller last cleared it: every
// SdfStats::record on this thread adds to it too. Embree runs user-geometry callbacks on the
// thread that called rtcIntersect1/rtcOccluded1, so a tracer that clears the tally before a
// pixel's rays and reads it after gets that pixel's steps (the per-pixel heat map signal),
// with no lock and no change to the ray API.
struct SdfRayTally {
  std::uint64_t rays = 0, steps = 0, capped = 0;
  int maxSteps = 0;  // the most steps of one ray
};
SdfRayTally& threadSdfTally();

// An SDF object as the scene holds it: the tree, the tracer's settings, its object-space
// bounds (the Embree user primitive's box; rays are traced only inside it). Step statistics are
// kept by whoever traces it (RtScene), not here: one object may be traced by several scenes.
struct SdfObject {
  Sdf sdf;
  SphereTraceSettings settings;
  dvec3 lo{-1.0}, hi{1.0};
};

// Surface nets (Gibson 1998, "Constrained elastic surface nets"): one vertex per grid cell
// that the surface crosses, at the mean of its edges' linear zero crossings; one quad per
// crossed grid edge joining the four cells around it. `cells` per axis over the padded
// bounds. Counter-clockwise seen from outside (f > 0), normals from sdfNormal.
// Its cost is (cells + 1)^3 distance evaluations of every node; loaders and the geometry axis
// refuse more than kMaxSdfEvaluations (e.g. 256^3 x 89 nodes, or 64^3 x 1024).
inline constexpr double kMaxSdfEvaluations = 1.5e9 * kSdfWorkLimitScale;
struct Mesh;
Mesh polygonizeSdf(const Sdf& sdf, const dvec3& lo, const dvec3& hi, int cells);

}  // namespace diptych
