#pragma once
// The Embree scene built from a WorldGeometry: one triangle geometry per WorldMesh, with
// geomID == instance index, holding exactly the same float positions and index triples, so a
// hit (geomID, primID, u, v) reconstructs with interpolatePosition() to the point Embree tested.
#include <embree3/rtcore.h>

#include <atomic>
#include <cstdint>
#include <optional>
#include <span>

#include "engine/rt/rt_device.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/world_geometry.h"

namespace diptych {

struct Hit {
  int instance = -1;            // == WorldMesh index == Scene instance index
  std::uint32_t primitive = 0;  // triangle index in that WorldMesh
  float u = 0.f, v = 0.f;       // Embree barycentrics: u weights vertex 1, v weights vertex 2
  float t = 0.f;                // distance along the ray in units of |direction|
  vec3 Ng{0.f};  // Embree's unnormalised geometric normal; points like the CCW face normal (tested)
};

// A segment [tnear, tfar] of origin + t * direction. tnear > tfar marks an inactive ray
// (Embree's stream convention); an inactive ray reports "not occluded".
struct OcclusionRay {
  vec3 origin{0.f};
  vec3 direction{0.f};
  float tnear = 0.f;
  float tfar = 0.f;
};

struct RtSceneOptions {
  RTCBuildQuality quality = RTC_BUILD_QUALITY_MEDIUM;
  // RTC_SCENE_FLAG_ROBUST: watertight traversal, no missed hits on shared edges or at grazing
  // angles, at some speed cost. Exactness is the engine's reason to trace rays, so it is on.
  bool robust = true;
};

class RtScene {
 public:
  // The device must outlive the scene. Empty WorldMeshes get no geometry (their id is unused).
  // Throws Error (with the Embree error code) if Embree rejects the data.
  RtScene(const RtDevice& device, const WorldGeometry& world, RtSceneOptions options = {});
  ~RtScene();
  RtScene(const RtScene&) = delete;
  RtScene& operator=(const RtScene&) = delete;

  // Closest hit of ray.origin + t * ray.direction for t in [tnear, tfar].
  std::optional<Hit> intersect(const Ray& ray, float tnear, float tfar) const;
  // Any hit in [tnear, tfar].
  bool occluded(const vec3& origin, const vec3& direction, float tnear, float tfar) const;

  // Many occlusion rays: occludedOut[i] = 1 when rays[i] hits something, else 0. Split into
  // tiles traced with Embree's ray-stream API (rtcOccluded1M) in parallel with TBB.
  // `coherent` hints that neighbouring rays are similar (camera-like), otherwise incoherent.
  void occludedBatch(std::span<const OcclusionRay> rays, std::span<std::uint8_t> occludedOut,
                     bool coherent = false) const;

  // Rays traced by this scene since construction or the last reset (all entry points, all
  // threads): benchmarks divide by time for rays per second.
  std::uint64_t raysTraced() const { return raysTraced_.load(std::memory_order_relaxed); }
  void resetRayCount() { raysTraced_.store(0, std::memory_order_relaxed); }

  RTCScene handle() const { return scene_; }

  // Hook for alpha-masked materials (AlphaMode::Mask), to be implemented: an intersection and
  // occlusion filter function per geometry (rtcSetGeometryIntersectFilterFunction /
  // rtcSetGeometryOccludedFilterFunction) that samples the colour texture alpha at the hit's
  // uv and rejects the hit below alphaCutoff. Each geometry's user data already points at its
  // WorldMesh for that purpose.

 private:
  const RtDevice& device_;
  RTCScene scene_ = nullptr;
  mutable std::atomic<std::uint64_t> raysTraced_{0};
};

}  // namespace diptych
