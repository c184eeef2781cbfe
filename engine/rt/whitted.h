#pragma once
// The lecture's recursive ray tracer (Tema 5, RAYTRACING / EVALUAMILREC / DIRECTA), sharing the
// shading code of the hybrid passes (shaders/common/shading.glsl through engine/shading/shading.h):
//   RAYTRACING(o, u, n): n > max -> 0; miss -> environment radiance along u;
//                        hit p -> EVALUAMILREC(p, -u, n)
//   EVALUAMILREC: M_E + A_G + sum_i V_i S_i DIRECTA(p, v, l_i)
//                 + k_t M_T RAYTRACING(p, t, n + 1)  (if k_t > 0 and n < max)
//                 + k_ps M_PS RAYTRACING(p, r, n + 1) (if k_ps > 0 and n < max)
// V_i is traced with shadow rays (area lights: stratified samples). Depth counts as in the
// lecture: the primary ray has n = 1, and a surface at depth n spawns secondary rays only when
// n < maxDepth.
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "engine/rt/ray_cone.h"
#include "engine/rt/ray_counter.h"
#include "engine/rt/rt_scene.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/camera_math.h"

namespace diptych {

// One node of the lecture's ray tree: a ray cast at some depth and what it hit.
struct RayTreeEvent {
  Ray ray;
  int depth = 1;
  std::optional<Hit> hit;
};

// The texture footprint of a point's two secondary hits (a caller's, e.g. the passes'
// texture_samples): the colour and coverage that replace the reflected or the transmitted ray's
// own lookup at its hit (applyTextureSignal). w < 0: none, the hit's own lookup. hops > 0: the
// signal is for a hit further along the same kind of ray, past that many hits (a solid glass's
// far side: the ground is the transmitted ray's second hit): each hit passes it on to its own ray
// of that kind, one hop less (WhittedTracer::passSignal).
struct SecondarySignals {
  vec4 reflection{-1.f};
  vec4 transmission{-1.f};
  int reflectionHops = 0, transmissionHops = 0;
};

struct WhittedSettings {
  int maxDepth = 5;      // the lecture's max
  int areaSamples = 16;  // stratified shadow rays per area light
  // Texture LOD at hits reached with a ray cone (engine/rt/ray_cone.h); false: level 0.
  bool rayCones = false;
  // Tiles (radianceTile's secondary rays, tracedTile) find their closest hits as Embree streams
  // (RtScene::intersectRays); false: one rtcIntersect1 each, as radiance() does, so that a tile
  // equals the ray-by-ray recursion bit for bit (the streams' packet kernels may round
  // differently at a shared triangle edge: engine/rt/whitted_tile.cpp).
  bool streams = true;
};

class WhittedTracer {
 public:
  WhittedTracer(const Scene& scene, const WorldGeometry& world, const RtScene& rt,
                WhittedSettings settings);

  // The ray that reflected() (reflection true) or transmitted() traces from point, for callers
  // that trace many at once (RtScene::intersectRays, then radianceTile at `depth` with `seed`
  // and the cone, then attenuated()); false when depth >= maxDepth (the radiance is 0).
  struct SecondaryRay {
    Ray ray;
    int depth = 0;  // of the ray's hit
    std::uint32_t seed = 0;
    RayCone cone{};  // when hasCone
    bool hasCone = false;
    bool inside = false;  // travels inside the point's volume: Beer-Lambert over its length
    int material = -1;    // the point's
    // Replaces the colour lookup at the ray's hit (applyTextureSignal); w < 0: none. And what
    // the hit passes on to its own secondary rays (hops). Both are read only when `signalled`
    // (set, with both, by passSignal; secondaryRay clears it): the recursion's rays without a
    // footprint, nearly all of them, neither write nor read them.
    bool signalled = false;
    vec4 textureSignal;
    SecondarySignals forward;
  };
  // The part of `signals` (a point's) for its secondary ray `ray` of the given kind: the signal
  // itself when it is for that ray's hit (hops 0), else passed on with one hop less.
  static void passSignal(const SecondarySignals& signals, bool reflection, SecondaryRay& ray);
  bool secondaryRay(const SurfacePoint& point, const vec3& v, int depth, std::uint32_t seed,
                    const RayCone* cone, bool reflection, SecondaryRay& out) const;
  // The radiance the secondary ray brought from distance (its hit's, infinity on a miss),
  // Beer-Lambert attenuated when it travelled inside a volume.
  vec3 attenuated(const SecondaryRay& ray, const vec3& radiance, float distance) const;
  // radiance() along the secondary ray, attenuated().
  vec3 traced(const SecondaryRay& ray) const;

  // RAYTRACING(o, u, depth); the caller offsets o if it leaves a surface.
  // cone: the ray's cone at its origin, used for texture LOD when settings.rayCones is set.
  // hitDistance, when given, receives the distance to the hit (infinity on a miss).
  // textureSignal, when given: the texture_filtering signal that replaces the hit's own colour
  // lookup (applyTextureSignal; the Whitted reference's texture_samples at the camera ray's hit).
  // secondarySignals, when given: those of the hit's own reflected and transmitted rays (the
  // reference's texture_samples at the camera hit's secondary hits).
  vec3 radiance(const Ray& ray, int depth, std::uint32_t seed, const RayCone* cone = nullptr,
                float* hitDistance = nullptr, const vec4* textureSignal = nullptr,
                const SecondarySignals* secondarySignals = nullptr) const;
  // The rest of RAYTRACING(o, u, depth) once the ray's closest hit is known (hit: null on a
  // miss), for callers that trace many rays at once (RtScene::intersectRays); depth <= maxDepth.
  // radiance() is trace + this.
  vec3 radianceAt(const Ray& ray, int depth, std::uint32_t seed, const Hit* hit,
                  const RayCone* cone = nullptr, float* hitDistance = nullptr,
                  const vec4* textureSignal = nullptr,
                  const SecondarySignals* secondarySignals = nullptr) const;
  // Whether hits passed to radianceAt need Hit::Ng (an observer reads it).
  bool wantsHitNormal() const { return bool(observer_); }
  // radianceAt for a tile of up to kMaxTile rays (hits[i] null: a miss; seeds[i], cones[i]
  // each; cones empty: none) into out[i], with the direct light's shadow rays of all the tile's
  // points traced as one coherent Embree stream (neighbouring pixels aimed at the same lights)
  // instead of one rtcOccluded1 each (engine/rt/whitted_tile.cpp): the same arithmetic, up to
  // the rounding of Embree's packet kernels (see there). Their reflected and transmitted rays
  // are traced together the same way (tracedTile), level by level, while depth <
  // kBatchedDepths, and ray by ray, as radiance() does, from there on (each batched level holds
  // ~100 KB of stack, -fstack-usage: radianceTile 80 KB, tracedTile 19 KB; 8 levels stay well
  // inside TBB's 4 MB worker stacks, while the depth parameter goes up to 64). Tiles of 128
  // rather than 64: rt_transmission 0.96x, rt_reflection 0.97x CPU time on whitted 640x480
  // (whitted byte-identical; techniques' coplanar ties move: FLIP 2.9e-6). depth: 1..maxDepth (else
  // an Error), as for radianceAt: radiance() traces nothing beyond maxDepth. textureSignal: empty,
  // or one per ray (radiance()'s textureSignal); secondarySignals: empty, or one per ray
  // (radiance()'s).
  static constexpr std::size_t kMaxTile = 128;
  static constexpr int kBatchedDepths = 8;
  void radianceTile(std::span<const Ray> rays, std::span<const Hit* const> hits,
                    std::span<const std::uint32_t> seeds, int depth,
                    std::span<const RayCone* const> cones, std::span<vec3> out,
                    std::span<const vec4> textureSignal = {},
                    std::span<const SecondarySignals> secondarySignals = {}) const;
  // traced() of each ray (all of one depth, any number): their closest hits found by Embree
  // streams (RtScene::intersectRays) of kMaxTile rays, then radianceTile and attenuated().
  void tracedTile(std::span<const SecondaryRay> rays, std::span<vec3> out) const;
  // EVALUAMILREC at a known surface point seen from direction v (unit, toward the viewer); cone:
  // the cone's width at the point and its spread; secondarySignals: radiance()'s.
  vec3 shade(const SurfacePoint& point, const vec3& v, int depth, std::uint32_t seed,
             const RayCone* cone = nullptr,
             const SecondarySignals* secondarySignals = nullptr) const;
  // The secondary radiances of EVALUAMILREC, without their k M factors: L_in(p, r) and
  // L_in(p, t). Each returns 0 when depth >= maxDepth. signals: the point's (passSignal).
  vec3 reflected(const SurfacePoint& point, const vec3& v, int depth, std::uint32_t seed,
                 const RayCone* cone = nullptr, const SecondarySignals* signals = nullptr) const;
  vec3 transmitted(const SurfacePoint& point, const vec3& v, int depth, std::uint32_t seed,
                   const RayCone* cone = nullptr, const SecondarySignals* signals = nullptr) const;

  std::uint64_t raysTraced() const { return rays_.total(); }
  // Called for every RAYTRACING call (not shadow rays), for inspecting or testing the ray tree.
  // Must be thread-safe if the tracer is used from several threads.
  void setRayObserver(std::function<void(const RayTreeEvent&)> observer) {
    observer_ = std::move(observer);
  }
  const WhittedSettings& settings() const { return settings_; }

 private:
  vec3 direct(const SurfacePoint& point, const vec3& v, std::uint32_t seed) const;
  // DIRECTA's light i at point seen from v, up to its visibility V_i: false when it adds
  // nothing (no radiance there, or a zero response: its shadow rays are skipped); else its
  // sample, response and shadow-ray count (counted in raysTraced). direct() and radianceTile
  // share it, so both test and count alike.
  bool lightTerm(std::size_t i, const SurfacePoint& point, const vec3& v, shading::LightSample& s,
                 vec3& response, int& shadowRays) const;
  // radianceAt's steps: count the ray (and show it to the observer); the hit's surface point,
  // with its texture LOD from the ray's cone where asked (coned: then `at` is the cone at the
  // point); EVALUAMILREC given the direct light's sum.
  void countRay(const Ray& ray, int depth, const Hit* hit) const;
  // countRay without the count (radianceTile counts its whole tile at once).
  void observeRay(const Ray& ray, int depth, const Hit* hit) const {
    if (observer_) observer_({ray, depth, hit ? std::optional<Hit>(*hit) : std::nullopt});
  }
  SurfacePoint surfaceAt(const Ray& ray, const Hit& hit, const RayCone* cone, RayCone& at,
                         bool& coned) const;
  vec3 shadeGiven(const SurfacePoint& point, const vec3& v, int depth, std::uint32_t seed,
                  const RayCone* cone, const vec3& directSum,
                  const SecondarySignals* secondarySignals = nullptr) const;
  // EVALUAMILREC's sum at p given its direct light and its secondary radiances (L_in(p, r),
  // L_in(p, t), 0 where not traced): shadeGiven's and radianceTile's, one expression.
  vec3 composed(const SurfacePoint& point, const vec3& v, const vec3& directSum,
                const vec3& reflected, const vec3& transmitted) const;
  const Scene& scene_;
  const WorldGeometry& world_;
  const RtScene& rt_;
  WhittedSettings settings_;
  std::vector<shading::ShadingLight> lights_;  // scene_.lights converted once, not per hit
  RayCounter rays_;
  std::function<void(const RayTreeEvent&)> observer_;
};

}  // namespace diptych
