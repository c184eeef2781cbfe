#pragma once
// Exact light visibility by shadow rays: the ray-traced producer of the "light visibility"
// slot (visibility in [0,1] per light per point).
#include <cstdint>
#include <span>
#include <vector>

#include "engine/rt/rt_scene.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/scene.h"

namespace diptych {
namespace shading {
struct ShadingLight;  // engine/shading/shading.h
}

// A receiver: a point on the world geometry and its unit geometric (face) normal, either side.
// magnitude: per-axis max |vertex coordinate| of its triangle (SurfacePoint::positionMagnitude);
// zero means "use the position itself" (the paper's plain offset).
// time: the shutter time of the ray that found the point (SurfacePoint::time), which its shadow
// rays keep, so that a moving occluder is where it was when the point was seen.
struct ShadowReceiver {
  vec3 position{0.f};
  vec3 geometricNormal{0.f};
  vec3 magnitude{0.f};
  float time = kFrameTime;
};

// The receiver at a surface hit: the position, face normal and offset magnitude that
// makeSurfacePoint() computes, bit for bit, without resolving the material (a shadow ray needs
// none). Throws Error for an instance or primitive out of range.
ShadowReceiver shadowReceiver(const WorldGeometry& world, const SurfaceHit& hit);

// The shadow ray for one receiver and one light, as traced by traceShadowRays():
//  - origin: offsetRayOrigin() along the geometric normal, flipped to the light's side (so a
//    receiver facing away from the light is still traced, from its back side; the shading
//    term max(0, n.l) decides what it contributes);
//  - point, spot and area lights (area lights as a point at their centre for now): toward the
//    light position, stopping short by shadowSegmentTo()'s relative margin;
//  - directional lights: along -direction with tfar = infinity.
// A light with castsShadows == false, or a degenerate segment, yields an inactive ray
// (tnear > tfar), which counts as visible.
OcclusionRay makeShadowRay(const Light& light, const ShadowReceiver& receiver);

// The same toward an explicit point on the light (an area-light sample).
OcclusionRay makeShadowRayTo(const Light& light, const ShadowReceiver& receiver,
                             const vec3& target);

// Rays per receiver for this light: stratifiedSampleCount(areaSamples) for area lights with
// areaSamples > 1, else 1 (punctual lights, or area lights approximated by their centre).
int shadowRaysPerReceiver(const Light& light, int areaSamples);

// Ray `sample` of `count` for a receiver; area lights use stratified points on the light
// (engine/rt/light_sampling.h) jittered by `seed`.
OcclusionRay makeShadowSample(const Light& light, const ShadowReceiver& receiver, int sample,
                              int count, std::uint32_t seed);

// V_i for one receiver: the fraction of unoccluded rays (single-ray queries; for recursive
// tracers). Same rays as traceShadowRays for the same seed.
float lightVisibility(const RtScene& rt, const Light& light, const ShadowReceiver& receiver,
                      int areaSamples, std::uint32_t seed);

// Distance from the receiver to the first occluder along its shadow ray toward the light's
// centre (makeShadowRay), in world units; +infinity when nothing occludes it or the ray is
// inactive. The contact test of the shadow-bias classes (docs/shadow-bias.md §3) reads it.
float occluderDistance(const RtScene& rt, const Light& light, const ShadowReceiver& receiver);

// visibility[l * receivers.size() + p] in {0, 1} for light l and receiver p (fractions once
// area lights are sampled). One ray per receiver per light, traced in parallel tiles through
// RtScene::occludedBatch (Embree ray streams, TBB).
// With areaSamples > 1, area lights are sampled with that many stratified rays per receiver
// and the visibility is the unoccluded fraction. seeds[p] jitters receiver p's pattern (the
// receiver index when empty); passes use the pixel index, as the Whitted tracer does, so that
// the hybrid and the reference trace the same shadow rays.
std::vector<float> traceShadowRays(const RtScene& rt, std::span<const Light> lights,
                                   std::span<const ShadowReceiver> receivers, int areaSamples = 1,
                                   std::span<const std::uint32_t> seeds = {});

// traceShadowRays for a run of receivers on the calling thread, every light at once:
// visibility[p * lights.size() + l] for receiver p and light l (receiver-major, as a pass
// writes a pixel's lights together). The rays are generated straight into a stack tile in
// receiver, light, sample order and traced as coherent Embree streams (rtcOccluded1M) of up to
// 256, as WhittedTracer::radianceTile traces a tile's shadow rays: no per-frame ray, receiver or
// result arrays. The same rays and fractions as traceShadowRays for the same seeds (seeds[p],
// the receiver index when empty).
// lit, when given (receiver-major as visibility), names the pairs worth a ray: where lit is 0
// the light sends the receiver nothing (lightReaches), no ray is traced and the visibility is 1.
void traceShadowTile(const RtScene& rt, std::span<const Light> lights,
                     std::span<const ShadowReceiver> receivers, int areaSamples,
                     std::span<const std::uint32_t> seeds, std::span<float> visibility,
                     std::span<const std::uint8_t> lit = {});

// Whether `light` sends any radiance to `position` (shading::sampleLight's radiance is not
// zero): not behind a one-sided area light, not outside a spot's cone. The Whitted reference
// traces no shadow ray where it does not (WhittedTracer::lightTerm, after pbrt-v4's
// PathIntegrator::SampleLd, which skips the ray when the light sample carries nothing), and
// neither does rt_shadows: the visibility it would measure multiplies zero in every shading.
bool lightReaches(const shading::ShadingLight& light, const vec3& position);
// Whether lightReaches can be false somewhere away from the light's own centre: spot, quad and
// disc lights and any light with a range. Point, directional and sphere lights reach every point
// (a per-receiver test, a square root and a division, would cost for nothing).
bool lightMayNotReach(const Light& light);

}  // namespace diptych
