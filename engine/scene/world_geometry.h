#pragma once
// The scene's triangles in world space, one WorldMesh per Instance (same index). The raster
// G-buffer and the Embree scene are both built from these arrays, so a (instance, primitive,
// barycentrics) triple names the same point on both sides, bit for bit.
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/scene/scene.h"

namespace diptych {

struct SdfStats;  // engine/scene/sdf.h

// The primitive of a G-buffer hits texel that names no triangle of its instance but its
// analytic surface: an analytic sphere drawn as a ray-cast impostor (engine/gl/gbuffer_raster.h,
// GBufferTargets::impostors). Readers lift it onto the exact surface (passes/common/hits_texel.h).
inline constexpr std::uint32_t kImpostorPrimitive = 0xffffffffu;

// An analytic shape placed by its instance transform. Rays are intersected in object space in
// double (intersectAnalytic); points and normals go back to world space once, rounded to float.
struct AnalyticInstance {
  AnalyticShape shape;
  std::shared_ptr<const SdfObject> sdf;  // set: the surface is this SDF (shape unused)
  dmat4 toWorld{1.0}, toObject{1.0};     // the instance transform and its inverse
  Aabb bounds;                           // world space, rounded outward
  vec3 magnitude{0.f};  // per-axis max |coordinate| of bounds: the rounding scale of its points
};

// The instance transform's three maps, in one place (inline: they run per ray and per hit).
// A world ray in object space; an affine map keeps t: o' + t d' is the image of o + t d.
struct ObjectRay {
  dvec3 origin, direction;
};
inline ObjectRay toObjectRay(const AnalyticInstance& a, const vec3& o, const vec3& d) {
  return {dvec3(a.toObject * glm::dvec4(dvec3(o), 1.0)),
          dvec3(a.toObject * glm::dvec4(dvec3(d), 0.0))};
}
// An object-space point in world space, rounded to float once.
inline vec3 toWorldPoint(const AnalyticInstance& a, const dvec3& p) {
  return vec3(dvec3(a.toWorld * glm::dvec4(p, 1.0)));
}
// An object-space normal in world space: the inverse transpose of the linear part, unit length.
inline vec3 toWorldNormal(const AnalyticInstance& a, const dvec3& n) {
  return vec3(glm::normalize(glm::transpose(glm::dmat3(a.toObject)) * n));
}

struct WorldMesh {
  int instance = 0;
  int material = -1;
  std::vector<vec3> positions;  // world space
  std::vector<vec3> normals;    // world space, unit length (computed when the mesh has none)
  std::vector<vec2> uvs;        // empty when the mesh has none
  // World-space unit tangent (xyz) and handedness w, bitangent = w cross(n, t); filled only for
  // meshes whose material has a normal map: TANGENT when the file has it (w negated for mirrored
  // instances), else generated from uv derivatives (computeVertexTangents).
  std::vector<vec4> tangents;
  std::vector<std::uint32_t> indices;  // winding flipped for mirrored instances
  // geometricNormal() of each triangle, computed once by flattenScene (12 bytes a triangle), so
  // that a ray hit reads it instead of a cross product, a square root and three divisions
  // (issue 14's profile). Empty in a mesh built by hand: geometricNormal then computes it.
  std::vector<vec3> faceNormals;
  bool mirrored = false;  // det(transform) < 0
  vec3 motion{0.f};  // Instance::motion: positions are at kFrameTime, displaced by it over time
  std::optional<AnalyticInstance> analytic;  // the exact surface, for ray tracers (see Mesh)
};

struct WorldGeometry {
  std::vector<WorldMesh> meshes;
  Aabb bounds;
  std::size_t triangleCount() const;
};

WorldGeometry flattenScene(const Scene& scene);

// Closest hit of the float world ray o + t d, t in [tmin, tmax], with the placed shape: the ray
// is taken to object space in double, so Embree's callback and a G-buffer texel lifted onto the
// shape (liftToAnalytic in engine/rt/surface_point.h) compute bit-identical hits for the same ray.
std::optional<ShapeHit> intersectAnalytic(const AnalyticInstance& a, const vec3& o, const vec3& d,
                                          float tmin, float tmax);
// The one-part variant (an Embree user primitive is one part). For an SDF object the sphere
// tracer's steps are recorded into `stats` when given (the caller owns the counters, so two
// ray-tracing scenes sharing one SdfObject keep separate figures).
std::optional<ShapeHit> intersectAnalyticPart(const AnalyticInstance& a, int part, const vec3& o,
                                              const vec3& d, float tmin, float tmax,
                                              SdfStats* stats = nullptr);
// Whether intersectAnalyticPart finds a hit, without computing it (occlusion queries skip
// the surface parameters of quadrics).
bool analyticPartOccludes(const AnalyticInstance& a, int part, const vec3& o, const vec3& d,
                          float tmin, float tmax, SdfStats* stats = nullptr);
// World point and unit outward normal ((M^-1)^T n, right for mirrors too) at a part's uv.
vec3 analyticPosition(const AnalyticInstance& a, int part, vec2 uv);
vec3 analyticNormal(const AnalyticInstance& a, int part, vec2 uv);
// Both, bit for bit, with the shape's trigonometry evaluated once (hot in the ray tracers).
void analyticPositionAndNormal(const AnalyticInstance& a, int part, vec2 uv, vec3& position,
                               vec3& normal);
// SDF objects: world unit normal (central differences at the tolerance) of an object-space hit
// point (its world point: toWorldPoint).
vec3 sdfNormal(const AnalyticInstance& a, const dvec3& objectPoint);
int analyticPartCount(const AnalyticInstance& a);
// Object-space box of one part (the SDF's bounds for SDF objects).
void analyticPartBounds(const AnalyticInstance& a, int part, dvec3& lo, dvec3& hi);
// That box's 8 corners mapped by toWorld: the part's world-space box, in double.
void analyticPartWorldBounds(const AnalyticInstance& a, int part, dvec3& lo, dvec3& hi);

// Exact world position of a hit: p = (1-u-v) p0 + u p1 + v p2 with Embree's barycentric
// convention (u weights vertex 1, v weights vertex 2), evaluated in one fixed order.
vec3 interpolatePosition(const WorldMesh& mesh, std::uint32_t primitive, float u, float v);
vec3 interpolateNormal(const WorldMesh& mesh, std::uint32_t primitive, float u, float v);
vec2 interpolateUv(const WorldMesh& mesh, std::uint32_t primitive, float u, float v);
// Unit normal of the CCW front face, (0, 1, 0) for a degenerate triangle: faceNormals' value
// when the mesh has them, bit for bit the computed one.
vec3 geometricNormal(const WorldMesh& mesh, std::uint32_t primitive);
// Interpolated xyz (not normalised) and the w of vertex 0; (0,0,0,1) when there are none.
vec4 interpolateTangent(const WorldMesh& mesh, std::uint32_t primitive, float u, float v);

// Per-vertex tangent frames from uv derivatives (Lengyel 2001, "Computing Tangent Space Basis
// Vectors for an Arbitrary Mesh"): per triangle T = dP/du and B = -dP/dv (glTF's v grows down
// the image while a normal map's +Y points up it), summed over the triangles of each vertex,
// T made orthogonal to n (Gram-Schmidt), w = sign(dot(cross(n, T), B)). MikkTSpace gives the
// same frames on meshes whose uv charts are not split within a vertex's fan; it differs in
// weighting (angle, not uv-area) and in splitting vertices at chart seams.
std::vector<vec4> computeVertexTangents(const std::vector<vec3>& positions,
                                        const std::vector<vec3>& normals,
                                        const std::vector<vec2>& uvs,
                                        const std::vector<std::uint32_t>& indices);

}  // namespace diptych
