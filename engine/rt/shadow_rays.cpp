#include "engine/rt/shadow_rays.h"

#include <tbb/parallel_for.h>

#include <limits>

#include "engine/rt/light_sampling.h"
#include "engine/rt/ray_offset.h"

namespace diptych {

OcclusionRay makeShadowRay(const Light& light, const ShadowReceiver& receiver) {
  return makeShadowRayTo(light, receiver, light.position);
}

OcclusionRay makeShadowRayTo(const Light& light, const ShadowReceiver& receiver,
                             const vec3& target) {
  OcclusionRay ray;
  ray.tnear = 0.f;
  ray.tfar = -1.f;  // inactive until proven otherwise
  if (!light.castsShadows) return ray;

  const bool directional = light.type == LightType::Directional;
  const vec3 towardLight = directional ? -light.direction : target - receiver.position;
  // Leave from the side of the surface that faces the light.
  const vec3 n = glm::dot(receiver.geometricNormal, towardLight) >= 0.f ? receiver.geometricNormal
                                                                        : -receiver.geometricNormal;
  ray.origin = offsetRayOrigin(receiver.position, n, receiver.magnitude);
  if (directional) {
    const float len = glm::length(towardLight);
    if (!(len > 0.f) || !std::isfinite(len)) return ray;
    ray.direction = towardLight / len;
    ray.tfar = std::numeric_limits<float>::infinity();
    return ray;
  }
  const ShadowSegment segment = shadowSegmentTo(ray.origin, target);
  ray.direction = segment.direction;
  ray.tfar = segment.tfar;  // < 0 (inactive) when the origin is at the light
  return ray;
}

int shadowRaysPerReceiver(const Light& light, int areaSamples) {
  return isAreaLight(light) && areaSamples > 1 ? stratifiedSampleCount(areaSamples) : 1;
}

OcclusionRay makeShadowSample(const Light& light, const ShadowReceiver& receiver, int sample,
                              int count, std::uint32_t seed) {
  if (count <= 1) return makeShadowRay(light, receiver);
  const vec2 s = stratifiedSample(sample, count, seed);
  return makeShadowRayTo(light, receiver, areaLightPoint(light, s, receiver.position));
}

float lightVisibility(const RtScene& rt, const Light& light, const ShadowReceiver& receiver,
                      int areaSamples, std::uint32_t seed) {
  const int count = shadowRaysPerReceiver(light, areaSamples);
  int visible = 0;
  for (int s = 0; s < count; ++s) {
    const OcclusionRay r = makeShadowSample(light, receiver, s, count, seed);
    visible += (r.tnear > r.tfar || !rt.occluded(r.origin, r.direction, r.tnear, r.tfar)) ? 1 : 0;
  }
  return float(visible) / float(count);
}

std::vector<float> traceShadowRays(const RtScene& rt, std::span<const Light> lights,
                                   std::span<const ShadowReceiver> receivers, int areaSamples,
                                   std::span<const std::uint32_t> seeds) {
  const std::size_t n = receivers.size();
  std::vector<float> visibility(lights.size() * n, 1.f);
  // One light at a time, in chunks, so that many area samples do not need all rays at once.
  constexpr std::size_t kChunkRays = std::size_t(1) << 20;
  for (std::size_t l = 0; l < lights.size(); ++l) {
    const int count = shadowRaysPerReceiver(lights[l], areaSamples);
    const std::size_t receiversPerChunk = std::max<std::size_t>(1, kChunkRays / std::size_t(count));
    std::vector<OcclusionRay> rays;
    std::vector<std::uint8_t> occluded;
    for (std::size_t first = 0; first < n; first += receiversPerChunk) {
      const std::size_t last = std::min(n, first + receiversPerChunk);
      rays.resize((last - first) * std::size_t(count));
      tbb::parallel_for(first, last, [&](std::size_t p) {
        for (int s = 0; s < count; ++s)
          rays[(p - first) * count + s] = makeShadowSample(
              lights[l], receivers[p], s, count, seeds.empty() ? std::uint32_t(p) : seeds[p]);
      });
      occluded.assign(rays.size(), 0);
      rt.occludedBatch(rays, occluded);
      tbb::parallel_for(first, last, [&](std::size_t p) {
        int visible = 0;
        for (int s = 0; s < count; ++s) visible += occluded[(p - first) * count + s] ? 0 : 1;
        visibility[l * n + p] = float(visible) / float(count);
      });
    }
  }
  return visibility;
}

}  // namespace diptych
