// WhittedTracer::radianceTile and tracedTile: the first level of RAYTRACING for a tile of rays
// traced together, so that Embree sees coherent streams (rtcIntersect1M, rtcOccluded1M with
// RTC_INTERSECT_CONTEXT_FLAG_COHERENT: its 8/16-wide packet kernels) rather than one call per
// ray: the tile's closest hits, then the direct light's shadow rays of all its points. The
// arithmetic after Embree is radianceAt's: the same surface point, light samples and responses,
// the same shadow rays (makeShadowSample is lightVisibility's ray), the same visible fraction,
// the terms summed in the same order (shadeGiven), and radiance()'s recursion below. Embree's
// packet kernels may round differently from its single-ray ones: a ray through an edge shared
// by two triangles can get the other triangle, or t, u, v can differ in the last bits, and the
// recursion below can amplify that (docs/ray-tracing.md: 3 pixels of 76,800 on techniques.json's
// hybrid frame, FLIP mean 8.6e-5; whitted.json is byte-identical).
#include <array>
#include <cstddef>
#include <limits>
#include <new>
#include <optional>
#include <type_traits>
#include <vector>

#include "engine/core/check.h"
#include "engine/rt/light_sampling.h"
#include "engine/rt/shadow_rays.h"
#include "engine/rt/whitted.h"
#include "engine/scene/environment.h"
#include "engine/shading/shading.h"

namespace diptych {
namespace {

// Shadow rays per stream call, as traceShadowRays' tiles (48 bytes each on the stack).
constexpr std::size_t kStreamRays = 256;

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

  RTCRay stream[kStreamRays];  // RTC_ALIGN(16), as rtcOccluded1M requires
  std::uint32_t owner[kStreamRays];
  bool active[kStreamRays];
  std::size_t filled = 0;
  const auto flush = [&] {
    rt_.occludedTile({stream, filled}, true);
    // lightVisibility's count: an inactive ray (tnear > tfar) is visible.
    for (std::size_t i = 0; i < filled; ++i)
      pending[owner[i]].visible += active[i] && stream[i].tfar < 0.f ? 0 : 1;
    filled = 0;
  };

  for (std::size_t i = 0; i < n; ++i) {
    const Ray& ray = rays[i];
    countRay(ray, depth, hits[i]);
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
    const ShadowReceiver receiver{p.position, p.faceNormal, p.positionMagnitude};
    for (std::size_t l = 0; l < lights; ++l) {
      PendingLight& q = pending[i * lights + l];
      shading::LightSample s;
      if (!lightTerm(l, p, -ray.direction, s, q.response, q.count)) continue;
      q.radiance = s.radiance;
      for (int k = 0; k < q.count; ++k) {
        const OcclusionRay r = makeShadowSample(scene_.lights[l], receiver, k, q.count, seeds[i]);
        stream[filled] = toEmbreeRay(r);
        owner[filled] = std::uint32_t(i * lights + l);
        active[filled] = r.tnear <= r.tfar;
        if (++filled == kStreamRays) flush();
      }
    }
  }
  if (filled > 0) flush();

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
  for (std::size_t i = 0; i < n; ++i) {
    if (!shaded[i]) continue;
    // The reflected and transmitted rays ray by ray below this level: traced as streams level by
    // level they were slower (the tiles of the deeper levels hold a few rays each: 127.4 against
    // 120.8 CPU ms for the Whitted reference, docs/ray-tracing.md).
    out[i] =
        shadeGiven(*point(i), -rays[i].direction, depth, seeds[i], coned[i] ? &cones[i] : nullptr,
                   directSum[i], secondarySignals.empty() ? nullptr : &secondarySignals[i]);
  }
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
    rt_.intersectRays({traced, n}, {hits, n}, {found, n}, wantsHitNormal());
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
