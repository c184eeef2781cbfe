#pragma once
// A unidirectional path tracer (J. T. Kajiya, "The Rendering Equation", SIGGRAPH 1986; the
// lecture's "Path-Tracing: iluminación indirecta o global"): the global-illumination reference.
//
// The lecture's material coefficients read as a BRDF (docs/reference-renderers.md has the
// derivation):
//   f = k_d C / pi                                     Lambert
//     + k_s d (e + 2) / (2 pi) max(0, r.v)^e           normalised Phong lobe (Lafortune and
//                                                      Willems 1994), r = reflection of l
//     + k_ps M_PS delta(mirror direction)              perfect mirror
//     + k_t  M_T  delta(refractLecture direction)      perfect refraction (Snell; on total
//                                                      internal reflection, the mirror direction)
//   M_E is emitted radiance. f governs the bounces; direct light from Scene::lights uses the
//   lecture's DIRECTA (no 1/pi: the lecture's light units), so the result equals rt_whitted
//   wherever there is no indirect light. A_G and k_a are NOT used: ambient light is the crude
//   stand-in for the indirect light that the path tracer computes.
// Light transport, each source counted by exactly one estimator:
//   - Scene::lights (point, spot, directional: delta lights; quad, disc, sphere area lights,
//     which have no geometry and can never be hit) by next-event estimation at every vertex;
//     an area light gets one point y sampled uniformly over an area A (areaLightPoint), whose
//     pdf per solid angle seen from the vertex is d^2 / (A cos_y);
//   - surfaces with M_E > 0 and the environment only when a BSDF-sampled ray hits them.
// Russian roulette (Arvo and Kirk 1990) after `rrDepth` vertices with survival probability
// min(1, max component of the throughput); `maxDepth` vertices at most.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/rt/rt_scene.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/camera_math.h"

namespace diptych {

struct PathSettings {
  int maxDepth = 16;  // surface hits per path (1 = emission + direct light only)
  int rrDepth = 3;    // Russian roulette from this many hits on
  bool russianRoulette = true;
  // Texture LOD by ray cones (engine/rt/ray_cone.h) along the camera ray and its delta (mirror,
  // refraction) bounces; a path that scatters off a smooth (diffuse, glossy, GGX) lobe returns
  // to level 0, since one cone cannot stand for a lobe's spread. false: level 0 everywhere.
  bool rayCones = false;
};

// Uniform numbers in [0,1) for one path: the PCG output permutation (pcgHash) of a 32-bit LCG
// state (O'Neill, "PCG: A Family of ... Random Number Generation", 2014), seeded by hashing
// (pixel, sample index, user seed), so that every pixel sample is reproducible on its own
// whatever the thread schedule.
class PathRng {
 public:
  PathRng() = default;  // a placeholder, to be assigned a seeded one
  PathRng(std::uint32_t pixel, std::uint32_t sample, std::uint32_t seed);
  float next();
  vec2 next2() {
    const float a = next();
    return {a, next()};
  }

 private:
  std::uint32_t state_ = 0;
};

struct PathSample {
  vec3 radiance{0.f};
  std::uint32_t rays = 0;  // intersection and shadow rays traced for this sample
  bool valid = true;       // false: a non-finite value arose (radiance set to 0)
};

class PathTracer {
 public:
  PathTracer(const Scene& scene, const WorldGeometry& world, const RtScene& rt,
             PathSettings settings);
  // Radiance arriving at ray.origin along -ray.direction; finite. coneSpread: the camera ray's
  // cone spread (pixelSpreadAngle; width 0 at the eye), used when settings.rayCones is set.
  PathSample radiance(const Ray& ray, PathRng& rng, float coneSpread = 0.f) const;
  // Up to kMaxPaths paths traced together, vertex by vertex (a wavefront, as the Whitted
  // tiles): each level's closest hits and next-event shadow rays go to Embree as streams, and
  // each path's arithmetic is radiance()'s, in its order. firstHits: the camera rays' hits
  // (CameraRays, which a caller traces as one coherent stream; null: a miss). rngs: each
  // path's sequence, advanced as radiance() advances it. Embree's stream kernels may round a
  // hit's last bits differently from its single-ray ones (docs/reference-renderers.md,
  // "Progressive rendering").
  static constexpr std::size_t kMaxPaths = 256;
  void radiance(std::span<const Ray> cameraRays, std::span<const Hit* const> firstHits,
                std::span<PathRng> rngs, float coneSpread, std::span<PathSample> out) const;
  const PathSettings& settings() const { return settings_; }

 private:
  struct LightTerm;
  class ShadowStream;
  struct PathState;
  // The bounce after vertex p at `depth` (BSDF sampling, cones, volume, Russian roulette):
  // false where the path ends there.
  bool scatter(const SurfacePoint& p, int depth, PathRng& rng, PathState& path) const;
  // Next-event estimation at p: per scene light, the term its shadow ray (added to `shadow`
  // where it is traced) lets through; the caller sums the unoccluded ones in light order.
  void nextEventTerms(const SurfacePoint& p, const vec3& v, PathRng& rng, LightTerm* terms,
                      std::uint32_t& rays, ShadowStream& shadow) const;
  const Scene& scene_;
  const WorldGeometry& world_;
  const RtScene& rt_;
  PathSettings settings_;
  std::vector<shading::ShadingLight> lights_;  // scene_.lights converted once, not per hit
};

}  // namespace diptych
