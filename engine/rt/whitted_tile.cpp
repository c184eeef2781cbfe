// WhittedTracer::radianceTile: RAYTRACING for a tile of rays whose closest hits are known, with
// the direct light's shadow rays of all the tile's points traced as one coherent Embree stream.
// Each point's result is radianceAt's bit for bit: the same surface point, the same light
// samples and responses, the same shadow rays (makeShadowSample is lightVisibility's ray), the
// same visible fraction, and the contributions summed in the same order (shadeGiven).
#include <vector>

#include "engine/core/check.h"

#include "engine/rt/light_sampling.h"
#include "engine/rt/ray_cone.h"
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
                                 const RayCone* cone, std::span<vec3> out) const {
  const std::size_t n = rays.size(), lights = lights_.size();
  DIPTYCH_CHECK(n <= kMaxTile && hits.size() == n && seeds.size() == n && out.size() >= n,
                "WhittedTracer::radianceTile: tile sizes disagree");
  // Per thread, reused tile after tile: no allocation per ray.
  thread_local std::vector<PendingLight> pending;
  pending.assign(n * lights, PendingLight{});
  SurfacePoint points[kMaxTile];
  RayCone cones[kMaxTile];
  bool shaded[kMaxTile];
  bool coned[kMaxTile];  // texture LOD by ray cone: shade with cones[i]

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
    shaded[i] = false;
    const Ray& ray = rays[i];
    countRay(ray, depth, hits[i]);
    if (!hits[i]) {
      out[i] = sampleEnvironment(scene_.environment, ray.direction);
      continue;
    }
    coned[i] = surfaceAt(ray, *hits[i], cone, points[i], cones[i]) != nullptr;
    shaded[i] = true;
    const SurfacePoint& p = points[i];
    const vec3 v = -ray.direction;
    // direct()'s tests, in its order; the shadow rays go to the stream instead of rtcOccluded1.
    const ShadowReceiver receiver{p.position, p.faceNormal, p.positionMagnitude};
    for (std::size_t l = 0; l < lights; ++l) {
      const Light& light = scene_.lights[l];
      const shading::LightSample s = shading::sampleLight(lights_[l], p.position);
      if (s.radiance == vec3(0.f)) continue;
      const vec3 response = shading::directResponse(p.resolved, p.shadingNormal, v, s.l);
      if (response == vec3(0.f)) continue;
      PendingLight& q = pending[i * lights + l];
      q.response = response;
      q.radiance = s.radiance;
      q.count = shadowRaysPerReceiver(light, settings_.areaSamples);
      rays_.add(std::uint64_t(q.count));
      for (int k = 0; k < q.count; ++k) {
        const OcclusionRay r = makeShadowSample(light, receiver, k, q.count, seeds[i]);
        stream[filled] = toEmbreeRay(r);
        owner[filled] = std::uint32_t(i * lights + l);
        active[filled] = r.tnear <= r.tfar;
        if (++filled == kStreamRays) flush();
      }
    }
  }
  if (filled > 0) flush();

  for (std::size_t i = 0; i < n; ++i) {
    if (!shaded[i]) continue;
    vec3 sum(0.f);
    for (std::size_t l = 0; l < lights; ++l) {
      const PendingLight& q = pending[i * lights + l];
      if (q.count == 0) continue;
      const float visibility = float(q.visible) / float(q.count);
      sum += shading::lightContributionOf(q.response, {vec3(0.f), 0.f, q.radiance}, visibility);
    }
    out[i] = shadeGiven(points[i], -rays[i].direction, depth, seeds[i],
                        coned[i] ? &cones[i] : nullptr, sum);
  }
}

}  // namespace diptych
