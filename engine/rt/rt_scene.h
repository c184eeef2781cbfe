#pragma once
// The Embree scene built from a WorldGeometry: one triangle geometry per WorldMesh, with
// geomID == instance index, holding exactly the same float positions and index triples, so a
// hit (geomID, primID, u, v) reconstructs with interpolatePosition() to the point Embree tested.
#include <embree3/rtcore.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "engine/rt/ray_counter.h"
#include "engine/rt/rt_device.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/sdf.h"
#include "engine/scene/world_geometry.h"

namespace diptych {

struct Hit {
  int instance = -1;            // == WorldMesh index == Scene instance index
  std::uint32_t primitive = 0;  // triangle index in that WorldMesh
  float u = 0.f, v = 0.f;       // Embree barycentrics: u weights vertex 1, v weights vertex 2
  float t = 0.f;                // distance along the ray in units of |direction|
  vec3 Ng{0.f};  // Embree's unnormalised geometric normal; points like the CCW face normal (tested)
  bool analytic = false;  // user geometry: primitive is the part, (u, v) its hit record
};

// A segment [tnear, tfar] of origin + t * direction. tnear > tfar marks an inactive ray
// (Embree's stream convention); an inactive ray reports "not occluded".
struct OcclusionRay {
  vec3 origin{0.f};
  vec3 direction{0.f};
  float tnear = 0.f;
  float tfar = 0.f;
  float time = kFrameTime;  // Ray::time: where moving instances are (camera_math.h)
};

// Every field of an Embree ray (mask all ones, id and flags 0, as the Embree 3 docs ask; time in
// the shutter interval, which only motion-blurred instances read).
inline void setEmbreeRay(RTCRay& e, const vec3& origin, const vec3& direction, float tnear,
                         float tfar, float time) {
  e.org_x = origin.x;
  e.org_y = origin.y;
  e.org_z = origin.z;
  e.tnear = tnear;
  e.dir_x = direction.x;
  e.dir_y = direction.y;
  e.dir_z = direction.z;
  e.time = time;
  e.tfar = tfar;
  e.mask = ~0u;
  e.id = 0;
  e.flags = 0;
}

// The Embree form of an occlusion ray, written
// field by field into its slot. No by-value form: assigning a returned RTCRay built it
// in 4-byte stores and copied it with 16-byte loads, a failed store-to-load forward per ray
// (perf annotate, issue 14).
inline void setEmbreeRay(RTCRay& e, const OcclusionRay& r) {
  setEmbreeRay(e, r.origin, r.direction, r.tnear, r.tfar, r.time);
}

struct RtSceneOptions {
  RTCBuildQuality quality = RTC_BUILD_QUALITY_MEDIUM;
  // RTC_SCENE_FLAG_ROBUST: watertight traversal, no missed hits on shared edges or at grazing
  // angles, at some speed cost. Exactness is the engine's reason to trace rays, so it is on.
  bool robust = true;
  // Instances with an analytic shape are intersected exactly (Embree user geometry) rather
  // than as their tessellation. Off: every instance is its triangles (what the rasterizer
  // draws), e.g. to compare the G-buffer with Embree triangle for triangle.
  bool analytic = true;
  // Meshes that a Scene places two or more times (same object-space triangles) are built once
  // and instanced (engine/rt/rt_scene_instancing.h); needs the Scene constructor. Off: every
  // instance is a world-space copy of its WorldMesh.
  bool instancing = true;
};

class RtScene {
 public:
  // The device must outlive the scene. Empty WorldMeshes get no geometry (their id is unused).
  // Throws Error (with the Embree error code) if Embree rejects the data. Without a Scene the
  // geometry is all opaque; with one (which must outlive this object, as `world` must),
  // alpha-masked materials cut out their holes (see geometryData below).
  RtScene(const RtDevice& device, const WorldGeometry& world, RtSceneOptions options = {});
  RtScene(const RtDevice& device, const WorldGeometry& world, const Scene& scene,
          RtSceneOptions options = {});
  ~RtScene();
  RtScene(const RtScene&) = delete;
  RtScene& operator=(const RtScene&) = delete;

  // Closest hit of ray.origin + t * ray.direction for t in [tnear, tfar]. wantNormal false:
  // Hit::Ng of an analytic quadric is left 0 (callers that rebuild the surface point from
  // (u, v), as makeSurfacePoint does, skip that work).
  std::optional<Hit> intersect(const Ray& ray, float tnear, float tfar,
                               bool wantNormal = true) const;
  // The same into `hit` (untouched on a miss); false on a miss. For the per-ray loops: no
  // std::optional<Hit> copied through the stack.
  bool intersect(const Ray& ray, float tnear, float tfar, Hit& hit, bool wantNormal) const;
  // Closest hits of many rays (t in [0, inf)), traced as coherent Embree streams
  // (rtcIntersect1M with RTC_INTERSECT_CONTEXT_FLAG_COHERENT, INCOHERENT on a scene with
  // instances: streamFlag) of kStreamRays on the calling
  // thread: Embree groups neighbouring rays into packets, so a row of pixel rays pays one
  // traversal setup per packet instead of one per ray. found[i] = &hits[i] on a hit, null on a
  // miss (hits[i] then untouched). The packet kernels may round differently from intersect's
  // single-ray ones (a ray through an edge shared by two triangles can get the other one, or
  // t, u, v can differ in the last bits: docs/ray-tracing.md).
  static constexpr std::size_t kStreamRays = 64;
  // coherent false: rays that scatter (a path tracer's bounces), traced with the INCOHERENT flag.
  void intersectRays(std::span<const Ray> rays, std::span<Hit> hits, std::span<const Hit*> found,
                     bool wantNormal, bool coherent = true) const;
  // Any hit in [tnear, tfar], at the shutter time `time`.
  bool occluded(const vec3& origin, const vec3& direction, float tnear, float tfar,
                float time = kFrameTime) const;

  // Many occlusion rays: occludedOut[i] = 1 when rays[i] hits something, else 0. Split into
  // tiles traced with Embree's ray-stream API (rtcOccluded1M) in parallel with TBB.
  // `coherent` hints that neighbouring rays are similar (camera-like), otherwise incoherent;
  // a scene with instances traces both as incoherent (streamFlag).
  void occludedBatch(std::span<const OcclusionRay> rays, std::span<std::uint8_t> occludedOut,
                     bool coherent = false) const;

  // One tile of Embree rays, built by the caller in its own per-thread buffer, traced as a
  // stream (rtcOccluded1M; ray by ray when the scene has alpha-filtered geometry, see the .cpp)
  // on the calling thread: rays[i].tfar becomes -inf where occluded.
  // Inactive rays (tnear > tfar) are left alone by Embree and not counted. traceShadowRays
  // generates its rays straight into such tiles, with no ray array for the whole frame.
  void occludedTile(std::span<RTCRay> rays, bool coherent) const;

  // Rays traced by this scene since construction or the last reset (all entry points, all
  // threads): benchmarks divide by time for rays per second.
  std::uint64_t raysTraced() const { return raysTraced_.total(); }
  void resetRayCount() { raysTraced_.reset(); }

  RTCScene handle() const { return scene_; }

  // What each Embree geometry's user data points at (geomID == instance index). Geometries
  // whose material has AlphaMode::Mask get an intersection and an occlusion filter function
  // that rejects a hit where the coverage at its uv is below the cutoff, so every query
  // (closest hit, any hit, streams) skips the holes. The coverage is resolveMaterial's alpha:
  // Material::alpha times the colour texture's alpha (sampleTexture; no texture when a checker
  // replaces the colour). AlphaMode::Blend geometry stays an opaque occluder for now. Analytic
  // and SDF instances test the same coverage inside their own callbacks (analytic_geometry.cpp).
  struct GeometryData {
    const WorldMesh* mesh = nullptr;
    const AnalyticInstance* analytic = nullptr;  // set for user geometry
    bool alphaMasked = false;
    float alpha = 1.f;                      // Material::alpha
    float alphaCutoff = 0.5f;               // Material::alphaCutoff
    const Texture* alphaTexture = nullptr;  // whose .w multiplies alpha; null: none
    bool instanced = false;   // an instance of a prototype (shared, or a moving instance's own)
    mat3 normalToWorld{1.f};  // instanced: the cofactor of the transform, for Hit::Ng
    std::unique_ptr<SdfStats> sdfStats;  // this scene's step counters of an SDF object
    // Coverage of triangle `primitive` at Embree barycentrics (u, v); read-only, thread-safe.
    float coverage(std::uint32_t primitive, float u, float v) const;
    // Coverage at a texture coordinate (analytic shapes: the hit's uv, the parameterisation
    // their tessellation's uvs follow, so both cut the same holes).
    float coverageAt(vec2 uv) const;
  };
  // Sphere-tracing steps per ray over every SDF object since the last reset (all queries,
  // closest-hit and occlusion alike, that reached an object's box).
  struct SdfStepStats {
    std::uint64_t rays = 0, steps = 0, capped = 0;  // capped: misses by the iteration cap
    int maxSteps = 0;
    double meanSteps() const { return rays ? double(steps) / double(rays) : 0.0; }
  };
  SdfStepStats sdfStepStats() const;
  void resetSdfStepStats() const;
  // Number of instances traced as analytic user geometry.
  int analyticGeometries() const { return analytic_; }
  // Number of geometries that cut alpha-mask holes (a filter function, or analytic callbacks).
  int alphaMaskedGeometries() const { return alphaMasked_; }
  // Instances traced through a shared prototype, and the number of prototypes built.
  int instancedGeometries() const { return instanced_; }
  // Instances with a motion (Instance::motion), traced as motion-blurred Embree instances.
  int movingGeometries() const { return moving_; }
  int prototypes() const { return int(prototypes_.size()); }

 private:
  RtScene(const RtDevice& device, const WorldGeometry& world, const Scene* scene,
          RtSceneOptions options);
  // The context flag of a stream: COHERENT where asked for and the scene has no instances (see
  // the .cpp), else INCOHERENT.
  RTCIntersectContextFlags streamFlag(bool coherent) const;
  // The Hit of a traced RTCRayHit (intersect's conversion); false on a miss.
  bool hitOf(const RTCRayHit& rh, Hit& hit, bool wantNormal) const;
  const RtDevice& device_;
  std::vector<GeometryData> geometry_;  // one per WorldMesh; sized once, addresses are stable
  int alphaMasked_ = 0;
  int analytic_ = 0;
  int instanced_ = 0;
  int moving_ = 0;
  RTCScene scene_ = nullptr;
  std::vector<RTCScene> prototypes_;  // released after scene_
  RayCounter raysTraced_;
};

}  // namespace diptych
