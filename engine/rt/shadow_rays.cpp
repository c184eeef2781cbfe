#include "engine/rt/shadow_rays.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "engine/core/error.h"
#include "engine/rt/light_sampling.h"
#include "engine/rt/occlusion_stream.h"
#include "engine/rt/ray_offset.h"
#include "engine/scene/analytic_hit.h"
#include "engine/shading/shading.h"

namespace diptych {

namespace {

// The shadow rays of one receiver toward one light. A ray leaves from offsetRayOrigin() on the
// side of the surface that faces its target; the origin depends only on that side, so it is
// computed at most once per side here (an area light's samples share it) instead of once per
// ray. Bit for bit the rays makeShadowRayTo() documents.
class ReceiverRays {
 public:
  ReceiverRays(const Light& light, const ShadowReceiver& receiver)
      : light_(light), receiver_(receiver) {}

  OcclusionRay to(const vec3& target) {
    OcclusionRay ray;
    ray.tnear = 0.f;
    ray.tfar = -1.f;  // inactive until proven otherwise
    ray.time = receiver_.time;
    if (!light_.castsShadows) return ray;
    const bool directional = light_.type == LightType::Directional;
    const vec3 towardLight = directional ? -light_.direction : target - receiver_.position;
    // Leave from the side of the surface that faces the light.
    ray.origin = origin(glm::dot(receiver_.geometricNormal, towardLight) >= 0.f);
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

  // Ray `sample` of `count` (makeShadowSample).
  OcclusionRay sample(int sample, int count, std::uint32_t seed) {
    if (count <= 1) return to(light_.position);
    const vec2 s = stratifiedSample(sample, count, seed);
    return to(areaLightPoint(light_, s, receiver_.position));
  }

 private:
  const vec3& origin(bool front) {
    const int side = front ? 0 : 1;
    if (!known_[side]) {
      origin_[side] = offsetRayOrigin(
          receiver_.position, front ? receiver_.geometricNormal : -receiver_.geometricNormal,
          receiver_.magnitude);
      known_[side] = true;
    }
    return origin_[side];
  }
  const Light& light_;
  const ShadowReceiver& receiver_;
  vec3 origin_[2];
  bool known_[2] = {false, false};
};

}  // namespace

ShadowReceiver shadowReceiver(const WorldGeometry& world, const SurfaceHit& hit) {
  if (hit.instance < 0 || hit.instance >= int(world.meshes.size()))
    throw Error("shadowReceiver: instance " + std::to_string(hit.instance) + " out of range");
  const WorldMesh& mesh = world.meshes[std::size_t(hit.instance)];
  if (hit.analytic && mesh.analytic) {
    const AnalyticInstance& a = *mesh.analytic;
    if (a.sdf) {  // SurfaceHit's SDF encoding: (u, v, bits of z) is the object-space point
      const dvec3 p(hit.u, hit.v, std::bit_cast<float>(hit.primitive));
      return {toWorldPoint(a, p), sdfNormal(a, p), a.magnitude};
    }
    if (int(hit.primitive) >= partCount(a.shape))
      throw Error("shadowReceiver: instance " + std::to_string(hit.instance) +
                  " has no analytic part " + std::to_string(hit.primitive));
    ShadowReceiver r;
    analyticHitPointAndNormal(a, int(hit.primitive), vec2(hit.u, hit.v), r.position,
                              r.geometricNormal);
    r.magnitude = a.magnitude;
    return r;
  }
  if (hit.analytic || std::size_t(hit.primitive) >= mesh.indices.size() / 3)
    throw Error("shadowReceiver: primitive " + std::to_string(hit.primitive) +
                " out of range in instance " + std::to_string(hit.instance));
  const std::uint32_t* tri = &mesh.indices[3 * std::size_t(hit.primitive)];
  return {interpolatePosition(mesh, hit.primitive, hit.u, hit.v),
          geometricNormal(mesh, hit.primitive),
          vertexMagnitude(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]])};
}

OcclusionRay makeShadowRay(const Light& light, const ShadowReceiver& receiver) {
  return makeShadowRayTo(light, receiver, light.position);
}

OcclusionRay makeShadowRayTo(const Light& light, const ShadowReceiver& receiver,
                             const vec3& target) {
  return ReceiverRays(light, receiver).to(target);
}

int shadowRaysPerReceiver(const Light& light, int areaSamples) {
  return isAreaLight(light) && areaSamples > 1 ? stratifiedSampleCount(areaSamples) : 1;
}

OcclusionRay makeShadowSample(const Light& light, const ShadowReceiver& receiver, int sample,
                              int count, std::uint32_t seed) {
  return ReceiverRays(light, receiver).sample(sample, count, seed);
}

float lightVisibility(const RtScene& rt, const Light& light, const ShadowReceiver& receiver,
                      int areaSamples, std::uint32_t seed) {
  const int count = shadowRaysPerReceiver(light, areaSamples);
  int visible = 0;
  ReceiverRays rays(light, receiver);
  for (int s = 0; s < count; ++s) {
    const OcclusionRay r = rays.sample(s, count, seed);
    visible +=
        (r.tnear > r.tfar || !rt.occluded(r.origin, r.direction, r.tnear, r.tfar, r.time)) ? 1 : 0;
  }
  return float(visible) / float(count);
}

float occluderDistance(const RtScene& rt, const Light& light, const ShadowReceiver& receiver) {
  const OcclusionRay r = makeShadowRay(light, receiver);
  const float inf = std::numeric_limits<float>::infinity();
  if (r.tnear > r.tfar) return inf;
  const float len = glm::length(r.direction);
  const auto hit =
      rt.intersect(Ray{r.origin, r.direction / len, r.time}, r.tnear * len, r.tfar * len);
  return hit ? hit->t : inf;
}

std::vector<float> traceShadowRays(const RtScene& rt, std::span<const Light> lights,
                                   std::span<const ShadowReceiver> receivers, int areaSamples,
                                   std::span<const std::uint32_t> seeds) {
  const std::size_t n = receivers.size();
  std::vector<float> visibility(lights.size() * n, 1.f);
  for (std::size_t l = 0; l < lights.size(); ++l) {
    const Light& light = lights[l];
    if (!light.castsShadows) continue;  // every ray inactive: visible
    const int count = shadowRaysPerReceiver(light, areaSamples);
    float* out = visibility.data() + l * n;
    // Each task generates its receivers' rays straight into a stream (neighbouring receivers
    // are neighbouring pixels, all aimed at one light) and counts the unoccluded ones: no
    // per-frame ray or result arrays, no second pass.
    const std::size_t grain = std::max<std::size_t>(1, kOcclusionStreamRays / std::size_t(count));
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        std::vector<int> visible(r.size(), 0);
                        const auto countVisible = [&](std::uint32_t p, bool v) { visible[p] += v; };
                        OcclusionStream<std::uint32_t, decltype(countVisible)> stream(rt, true,
                                                                                      countVisible);
                        for (std::size_t p = r.begin(); p < r.end(); ++p) {
                          ReceiverRays rays(light, receivers[p]);
                          const std::uint32_t seed = seeds.empty() ? std::uint32_t(p) : seeds[p];
                          for (int s = 0; s < count; ++s)
                            stream.add(rays.sample(s, count, seed), std::uint32_t(p - r.begin()));
                        }
                        stream.flush();
                        for (std::size_t p = r.begin(); p < r.end(); ++p)
                          out[p] = float(visible[p - r.begin()]) / float(count);
                      });
  }
  return visibility;
}

void traceShadowTile(const RtScene& rt, std::span<const Light> lights,
                     std::span<const ShadowReceiver> receivers, int areaSamples,
                     std::span<const std::uint32_t> seeds, std::span<float> visibility,
                     std::span<const std::uint8_t> lit) {
  const std::size_t n = receivers.size(), lightCount = lights.size();
  if (visibility.size() < n * lightCount)
    throw Error("traceShadowTile: visibility holds " + std::to_string(visibility.size()) +
                " values, not " + std::to_string(n * lightCount));
  if (!lit.empty() && lit.size() < n * lightCount)
    throw Error("traceShadowTile: lit holds " + std::to_string(lit.size()) + " flags, not " +
                std::to_string(n * lightCount));
  // Visible, and no rays: a light that casts no shadows, or one that sends this receiver nothing.
  const auto unshadowed = [&](std::size_t slot, const Light& light) {
    return !light.castsShadows || (!lit.empty() && !lit[slot]);
  };
  // Counts first (exact in float far beyond any ray count here), fractions at the end: the
  // same float(visible) / float(count) as traceShadowRays.
  std::fill_n(visibility.begin(), n * lightCount, 0.f);
  // The owner of a ray: the index into visibility of its receiver and light.
  const auto countVisible = [&](std::uint32_t slot, bool visible) { visibility[slot] += visible; };
  OcclusionStream<std::uint32_t, decltype(countVisible)> stream(rt, true, countVisible);
  for (std::size_t p = 0; p < n; ++p) {
    const std::uint32_t seed = seeds.empty() ? std::uint32_t(p) : seeds[p];
    for (std::size_t l = 0; l < lightCount; ++l) {
      const Light& light = lights[l];
      const std::size_t slot = p * lightCount + l;
      if (unshadowed(slot, light)) {
        visibility[slot] = 1.f;
        continue;
      }
      const int count = shadowRaysPerReceiver(light, areaSamples);
      ReceiverRays rays(light, receivers[p]);
      for (int s = 0; s < count; ++s) stream.add(rays.sample(s, count, seed), std::uint32_t(slot));
    }
  }
  stream.flush();
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t l = 0; l < lightCount; ++l)
      if (!unshadowed(p * lightCount + l, lights[l]))
        visibility[p * lightCount + l] /= float(shadowRaysPerReceiver(lights[l], areaSamples));
}

bool lightReaches(const shading::ShadingLight& light, const vec3& position) {
  return shading::sampleLight(light, position).radiance != vec3(0.f);
}

bool lightMayNotReach(const Light& light) {
  return light.type == LightType::Spot || light.type == LightType::QuadArea ||
         light.type == LightType::DiscArea || light.range > 0.f;
}

}  // namespace diptych
