#include "engine/rt/shadow_rays.h"

#include <tbb/parallel_for.h>

#include <limits>

#include "engine/rt/ray_offset.h"

namespace diptych {

OcclusionRay makeShadowRay(const Light& light, const ShadowReceiver& receiver) {
  OcclusionRay ray;
  ray.tnear = 0.f;
  ray.tfar = -1.f;  // inactive until proven otherwise
  if (!light.castsShadows) return ray;

  const bool directional = light.type == LightType::Directional;
  const vec3 towardLight = directional ? -light.direction : light.position - receiver.position;
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
  const ShadowSegment segment = shadowSegmentTo(ray.origin, light.position);
  ray.direction = segment.direction;
  ray.tfar = segment.tfar;  // < 0 (inactive) when the origin is at the light
  return ray;
}

std::vector<float> traceShadowRays(const RtScene& rt, std::span<const Light> lights,
                                   std::span<const ShadowReceiver> receivers) {
  const std::size_t n = receivers.size();
  std::vector<OcclusionRay> rays(lights.size() * n);
  tbb::parallel_for(std::size_t(0), rays.size(), [&](std::size_t i) {
    rays[i] = makeShadowRay(lights[i / n], receivers[i % n]);
  });
  std::vector<std::uint8_t> occluded(rays.size());
  rt.occludedBatch(rays, occluded);
  std::vector<float> visibility(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) visibility[i] = occluded[i] ? 0.f : 1.f;
  return visibility;
}

}  // namespace diptych
