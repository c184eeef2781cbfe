// WhittedTracer::radianceTile and tracedTile: the first level of RAYTRACING for a tile of rays
// traced together, so that Embree sees coherent streams (rtcIntersect1M, rtcOccluded1M with
// RTC_INTERSECT_CONTEXT_FLAG_COHERENT: its 8/16-wide packet kernels) rather than one call per
// ray: the tile's closest hits, then the direct light's shadow rays of all its points. The
// arithmetic after Embree is radianceAt's: the same surface point, light samples and responses,
// the same shadow rays (makeShadowSample is lightVisibility's ray), the same visible fraction,
// the terms summed in the same order (composed), and below them the same tree, traced level by
// level: each tile's secondary rays as the next tile (tracedTile), ray by ray past
// kBatchedDepths. Embree's packet kernels may round differently from its single-ray ones: a ray
// through an edge shared by two triangles can get the other triangle, t, u, v can differ in the
// last bits, a tie between coplanar faces can go the other way, and the recursion below can
// amplify that (docs/ray-tracing.md; whitted.json is byte-identical).
// WhittedSettings::streams off: rtcIntersect1 for every tile, bit for bit the ray-by-ray tree.
#include <array>
#include <cstddef>
#include <limits>
#include <new>
#include <optional>
#include <type_traits>
#include <vector>

#include "engine/core/check.h"
#include "engine/rt/light_sampling.h"
#include "engine/rt/occlusion_stream.h"
#include "engine/rt/shadow_rays.h"
#include "engine/rt/whitted.h"
#include "engine/scene/environment.h"
#include "engine/shading/shading.h"

namespace diptych {
namespace {

// A light whose response at a point is not zero: what its visibility will multiply.
struct PendingLight {
  vec3 response{0.f};
  vec3 radiance{0.f};
  int count = 0;  // shadow rays traced; 0: the light contributes nothing here
  int visible = 0;
};

}  // namespace

void WhittedTracer::radianceTile(std::span<const Ray> rays, std::span<const Hit* const> hits,
                                 std::span<const std::uint32_t> seeds, int depth,
                                 std::span<const RayCone* const> cone, std::span<vec3> out,
                                 std::span<const vec4> textureSignal,
                                 std::span<const SecondarySignals> secondarySignals) const {
  const std::size_t n = rays.size(), lights = lights_.size();
  DIPTYCH_CHECK(n <= kMaxTile && hits.size() == n && seeds.size() == n && out.size() >= n &&
                    (cone.empty() || cone.size() == n) &&
                    (textureSignal.empty() || textureSignal.size() == n) &&
                    (secondarySignals.empty() || secondarySignals.size() == n),
                "WhittedTracer::radianceTile: tile sizes disagree");
  // radianceAt's contract: the hits were traced at a depth the recursion reaches (radiance()
  // returns 0 beyond maxDepth without tracing, so a caller past it traced rays for nothing).
  DIPTYCH_CHECK(depth >= 1 && depth <= settings_.maxDepth,
                "WhittedTracer::radianceTile: depth outside 1..maxDepth");
  // Per thread, reused tile after tile: no allocation per ray. Read only until each point's
  // direct light is summed into directSum[], before any recursion below: a nested radianceTile on
  // this thread (a TBB worker stealing another row while it waits) may then reuse it.
  thread_local std::vector<PendingLight> pending;
  pending.assign(n * lights, PendingLight{});
  // Raw storage, each point constructed in place below: an array of SurfacePoint would run
  // its member initialisers over ~16 KB per tile first.
  alignas(SurfacePoint) std::byte pointStorage[kMaxTile * sizeof(SurfacePoint)];
  const auto point = [&](std::size_t i) {
    return std::launder(reinterpret_cast<SurfacePoint*>(pointStorage) + i);
  };
  RayCone cones[kMaxTile];
  bool shaded[kMaxTile] = {};
  bool coned[kMaxTile] = {};  // shade with cones[i] (texture LOD)

  // lightVisibility's count per pending light (owner: its index in pending).
  const auto countVisible = [&](std::uint32_t owner, bool visible) {
    pending[owner].visible += visible;
  };
  OcclusionStream<std::uint32_t, decltype(countVisible)> stream(rt_, true, countVisible);

  rays_.add(n);  // countRay's count for the whole tile: one add, not one per ray
  for (std::size_t i = 0; i < n; ++i) {
    const Ray& ray = rays[i];
    observeRay(ray, depth, hits[i]);
    if (!hits[i]) {
      out[i] = sampleEnvironment(scene_.environment, ray.direction);
      continue;
    }
    const RayCone* c = cone.empty() ? nullptr : cone[i];
    // In place (guaranteed copy elision): an assignment would copy the ~250-byte point.
    SurfacePoint& p = *::new (static_cast<void*>(point(i)))
                          SurfacePoint(surfaceAt(ray, *hits[i], c, cones[i], coned[i]));
    if (!textureSignal.empty()) applyTextureSignal(p, scene_, textureSignal[i]);
    shaded[i] = true;
    // direct()'s tests (lightTerm); the shadow rays go to the stream instead of rtcOccluded1.
    const ShadowReceiver receiver{p.position, p.faceNormal, p.positionMagnitude, p.time};
    for (std::size_t l = 0; l < lights; ++l) {
      PendingLight& q = pending[i * lights + l];
      shading::LightSample s;
      if (!lightTerm(l, p, -ray.direction, s, q.response, q.count)) continue;
      q.radiance = s.radiance;
      for (int k = 0; k < q.count; ++k)
        stream.add(makeShadowSample(scene_.lights[l], receiver, k, q.count, seeds[i]),
                   std::uint32_t(i * lights + l));
    }
  }
  stream.flush();

  // Every point's direct light, in direct()'s order, before any recursion (see pending).
  vec3 directSum[kMaxTile];
  for (std::size_t i = 0; i < n; ++i) {
    if (!shaded[i]) continue;
    vec3 sum(0.f);
    for (std::size_t l = 0; l < lights; ++l) {
      const PendingLight& q = pending[i * lights + l];
      if (q.count == 0) continue;
      const float visibility = float(q.visible) / float(q.count);
      sum += shading::lightContributionOf(q.response, {vec3(0.f), 0.f, q.radiance}, visibility);
    }
    directSum[i] = sum;
  }
  if (depth >= kBatchedDepths) {  // ray by ray below (radiance()), in bounded stack
    for (std::size_t i = 0; i < n; ++i)
      if (shaded[i])
        out[i] = shadeGiven(*point(i), -rays[i].direction, depth, seeds[i],
                            coned[i] ? &cones[i] : nullptr, directSum[i],
                            secondarySignals.empty() ? nullptr : &secondarySignals[i]);
    return;
  }
  // The tile's secondary rays (shadeGiven's: each point's transmitted, then reflected ray) traced
  // together, level by level: tracedTile streams them and shades their hits with radianceTile,
  // recursively, instead of one rtcIntersect1 and one recursive radiance() per ray. Raw storage,
  // each ray constructed where it is used (as pointStorage): default-constructing the array ran
  // the initialisers of 128 rays per tile (the mirror's tiles, whose rays end on the ground, were
  // slower for it).
  alignas(SecondaryRay) std::byte kidStorage[2 * kMaxTile * sizeof(SecondaryRay)];
  SecondaryRay* kids = std::launder(reinterpret_cast<SecondaryRay*>(kidStorage));
  std::size_t kidCount = 0;
  int transmittedKid[kMaxTile], reflectedKid[kMaxTile];
  const auto spawn = [&](std::size_t i, bool reflection) {
    const SurfacePoint& p = *point(i);
    if (reflection ? !shading::hasReflection(p.resolved, false)
                   : !shading::hasTransmission(p.resolved))
      return -1;
    SecondaryRay& kid = *::new (static_cast<void*>(kids + kidCount)) SecondaryRay;
    if (!secondaryRay(p, -rays[i].direction, depth, seeds[i], coned[i] ? &cones[i] : nullptr,
                      reflection, kid))
      return -1;
    if (!secondarySignals.empty()) passSignal(secondarySignals[i], reflection, kid);
    return int(kidCount++);
  };
  for (std::size_t i = 0; i < n; ++i) {
    transmittedKid[i] = shaded[i] ? spawn(i, false) : -1;
    reflectedKid[i] = shaded[i] ? spawn(i, true) : -1;
  }
  vec3 kidRadiance[2 * kMaxTile];
  if (kidCount > 0) tracedTile({kids, kidCount}, {kidRadiance, kidCount});
  const auto radianceOf = [&](int kid) { return kid >= 0 ? kidRadiance[kid] : vec3(0.f); };
  for (std::size_t i = 0; i < n; ++i)
    if (shaded[i])
      out[i] = composed(*point(i), -rays[i].direction, directSum[i], radianceOf(reflectedKid[i]),
                        radianceOf(transmittedKid[i]));
}

void WhittedTracer::tracedTile(std::span<const SecondaryRay> rays, std::span<vec3> out) const {
  DIPTYCH_CHECK(out.size() >= rays.size(), "WhittedTracer::tracedTile: output too small");
  for (std::size_t begin = 0; begin < rays.size(); begin += kMaxTile) {
    const std::size_t n = std::min(kMaxTile, rays.size() - begin);
    const SecondaryRay* s = rays.data() + begin;
    Ray traced[kMaxTile];
    Hit hits[kMaxTile];
    const Hit* found[kMaxTile];
    for (std::size_t i = 0; i < n; ++i) traced[i] = s[i].ray;
    if (settings_.streams) {
      rt_.intersectRays({traced, n}, {hits, n}, {found, n}, wantsHitNormal());
    } else {
      for (std::size_t i = 0; i < n; ++i)
        found[i] = rt_.intersect(traced[i], 0.f, std::numeric_limits<float>::infinity(), hits[i],
                                 wantsHitNormal())
                       ? &hits[i]
                       : nullptr;
    }
    std::uint32_t seeds[kMaxTile];
    const RayCone* cones[kMaxTile];
    // Footprint signals (passSignal) are copied for radianceTile only where a ray of the tile
    // carries one: the footprint is off in every frame but an exact texture frame's.
    bool signalled = false;
    vec3 radiance[kMaxTile];
    for (std::size_t i = 0; i < n; ++i) {
      DIPTYCH_CHECK(s[i].depth == s[0].depth, "WhittedTracer::tracedTile: rays of two depths");
      seeds[i] = s[i].seed;
      cones[i] = s[i].hasCone ? &s[i].cone : nullptr;
      signalled = signalled || s[i].signalled;
    }
    std::optional<std::array<vec4, kMaxTile>> signals;
    std::optional<std::array<SecondarySignals, kMaxTile>> forwards;
    if (signalled) {
      signals.emplace();
      forwards.emplace();
      for (std::size_t i = 0; i < n; ++i) {
        (*signals)[i] = s[i].signalled ? s[i].textureSignal : vec4(-1.f);
        (*forwards)[i] = s[i].signalled ? s[i].forward : SecondarySignals{};
      }
    }
    radianceTile({traced, n}, {found, n}, {seeds, n}, s[0].depth, {cones, n}, {radiance, n},
                 signals ? std::span<const vec4>(signals->data(), n) : std::span<const vec4>(),
                 forwards ? std::span<const SecondarySignals>(forwards->data(), n)
                          : std::span<const SecondarySignals>());
    for (std::size_t i = 0; i < n; ++i) {
      // radiance()'s hitDistance.
      const float distance = found[i] ? hits[i].t * glm::length(traced[i].direction)
                                      : std::numeric_limits<float>::infinity();
      out[begin + i] = attenuated(s[i], radiance[i], distance);
    }
  }
}

}  // namespace diptych
