#include "engine/rt/whitted.h"

#include <limits>
#include <new>
#include <type_traits>

#include "engine/rt/camera_rays.h"
#include "engine/rt/light_sampling.h"
#include "engine/rt/ray_cone.h"
#include "engine/rt/shadow_rays.h"
#include "engine/scene/environment.h"
#include "engine/shading/shading.h"

namespace diptych {

WhittedTracer::WhittedTracer(const Scene& scene, const WorldGeometry& world, const RtScene& rt,
                             WhittedSettings settings)
    : scene_(scene), world_(world), rt_(rt), settings_(settings) {
  for (const Light& light : scene.lights) lights_.push_back(shading::toShadingLight(light));
}

vec3 WhittedTracer::radiance(const Ray& ray, int depth, std::uint32_t seed, const RayCone* cone,
                             float* hitDistance, const vec4* textureSignal,
                             const SecondarySignals* secondarySignals) const {
  if (depth > settings_.maxDepth) return vec3(0.f);
  // Hit::Ng only for an observer: the shading rebuilds the normal (makeSurfacePoint).
  // Depth 1 is the camera ray: it does not see back faces of single-sided materials.
  Hit h;
  const bool found =
      depth == 1
          ? CameraRays{rt_, scene_, world_}.intersect(ray, h, wantsHitNormal())
          : rt_.intersect(ray, 0.f, std::numeric_limits<float>::infinity(), h, wantsHitNormal());
  return radianceAt(ray, depth, seed, found ? &h : nullptr, cone, hitDistance, textureSignal,
                    secondarySignals);
}

vec3 WhittedTracer::radianceAt(const Ray& ray, int depth, std::uint32_t seed, const Hit* hit,
                               const RayCone* cone, float* hitDistance, const vec4* textureSignal,
                               const SecondarySignals* secondarySignals) const {
  countRay(ray, depth, hit);
  if (hitDistance)
    *hitDistance =
        hit ? hit->t * glm::length(ray.direction) : std::numeric_limits<float>::infinity();
  if (!hit) return sampleEnvironment(scene_.environment, ray.direction);
  RayCone at;
  bool coned = false;
  SurfacePoint p = surfaceAt(ray, *hit, cone, at, coned);
  if (textureSignal) applyTextureSignal(p, scene_, *textureSignal);
  return shade(p, -ray.direction, depth, seed, coned ? &at : nullptr, secondarySignals);
}

void WhittedTracer::countRay(const Ray& ray, int depth, const Hit* hit) const {
  rays_.add(1);
  observeRay(ray, depth, hit);
}

SurfacePoint WhittedTracer::surfaceAt(const Ray& ray, const Hit& h, const RayCone* cone,
                                      RayCone& at, bool& coned) const {
  // Returned by value into the caller's object (no ~250-byte copy of a point just written by
  // narrower stores: a store-forwarding stall per ray, perf annotate).
  SurfacePoint p = makeSurfacePoint(scene_, world_, {h.instance, h.primitive, h.u, h.v, h.analytic},
                                    ray.direction);
  atShutterTime(p, world_, ray.time);
  coned = cone && settings_.rayCones;
  if (!coned) return p;
  at = {cone->width + cone->spread * h.t * glm::length(ray.direction), cone->spread};
  p.resolved = resolveMaterial(scene_, scene_.material(p.material), p.uv,
                               coneUvLod(world_, p, ray.direction, at.width));
  return p;
}

bool WhittedTracer::lightTerm(std::size_t i, const SurfacePoint& p, const vec3& v,
                              shading::LightSample& s, vec3& response, int& shadowRays) const {
  s = shading::sampleLight(lights_[i], p.position);
  if (s.radiance == vec3(0.f)) return false;  // no contribution: skip its shadow rays
  // The response first, the shadow rays only where it is not zero (pbrt-v4's
  // PathIntegrator::SampleLd tests f before Unoccluded): V_i S_i 0 is 0 whatever V_i is, so the
  // image is the same bit for bit. This skips most shadow rays of mirror and glass hits: the
  // light behind the surface (n.l <= 0, no k_a), or a glossy lobe pow(r.v, e) underflowing to
  // 0 away from the highlight when k_d is 0.
  response = shading::directResponse(p.resolved, p.shadingNormal, v, s.l);
  if (response == vec3(0.f)) return false;
  shadowRays = shadowRaysPerReceiver(scene_.lights[i], settings_.areaSamples);
  rays_.add(std::uint64_t(shadowRays));
  return true;
}

vec3 WhittedTracer::direct(const SurfacePoint& p, const vec3& v, std::uint32_t seed) const {
  vec3 sum(0.f);
  const ShadowReceiver receiver{p.position, p.faceNormal, p.positionMagnitude, p.time};
  for (std::size_t i = 0; i < lights_.size(); ++i) {
    shading::LightSample s;
    vec3 response;
    int shadowRays = 0;
    if (!lightTerm(i, p, v, s, response, shadowRays)) continue;
    const float visibility =
        lightVisibility(rt_, scene_.lights[i], receiver, settings_.areaSamples, seed);
    sum += shading::lightContributionOf(response, s, visibility);
  }
  return sum;
}

vec3 WhittedTracer::shade(const SurfacePoint& p, const vec3& v, int depth, std::uint32_t seed,
                          const RayCone* cone, const SecondarySignals* secondarySignals) const {
  return shadeGiven(p, v, depth, seed, cone, direct(p, v, seed), secondarySignals);
}

vec3 WhittedTracer::shadeGiven(const SurfacePoint& p, const vec3& v, int depth, std::uint32_t seed,
                               const RayCone* cone, const vec3& directSum,
                               const SecondarySignals* secondarySignals) const {
  // The material's model says whether the signals exist (hasReflection, hasTransmission: as for
  // the hybrid's rt_reflection and rt_transmission); secondaryTerms weights them.
  const shading::ShadingMaterial& m = p.resolved;
  const vec3 trans = shading::hasTransmission(m)
                         ? transmitted(p, v, depth, seed, cone, secondarySignals)
                         : vec3(0.f);
  const vec3 refl = shading::hasReflection(m, false)
                        ? reflected(p, v, depth, seed, cone, secondarySignals)
                        : vec3(0.f);
  return composed(p, v, directSum, refl, trans);
}

vec3 WhittedTracer::composed(const SurfacePoint& p, const vec3& v, const vec3& directSum,
                             const vec3& reflected, const vec3& transmitted) const {
  const shading::ShadingMaterial& m = p.resolved;
  const vec3 rad = shading::emittedAndAmbient(m, scene_.ambient) + directSum;
  return rad + shading::secondaryTerms(m, p.shadingNormal, v, reflected, transmitted);
}

bool WhittedTracer::secondaryRay(const SurfacePoint& p, const vec3& v, int depth,
                                 std::uint32_t seed, const RayCone* cone, bool reflection,
                                 SecondaryRay& out) const {
  if (depth >= settings_.maxDepth) return false;
  vec3 direction;
  if (reflection) {
    direction = glm::normalize(shading::reflectAbout(v, p.shadingNormal));
    out.seed = pcgHash(seed ^ 0x52454646u);  // "REFF"
    out.hasCone = cone != nullptr;
    if (cone) out.cone = reflectedCone(world_, p, cone->width, cone->spread);
  } else {
    // Entering through the front face goes from air (1) into the material (ior); leaving goes
    // back out. Nested media are told apart by face orientation only (no medium stack).
    const float ior = scene_.material(p.material).ior;
    const float eta = p.frontFacing ? 1.f / ior : ior;
    direction = shading::refractLecture(v, p.shadingNormal, eta).t;
    out.seed = pcgHash(seed ^ 0x5452414eu);  // "TRAN"
    out.hasCone = cone != nullptr;
    if (cone) out.cone = *cone;
  }
  // KHR_materials_volume: a ray that leaves p into the back side of its (outward, CCW) face
  // travels inside the material's volume, to the next hit: Beer-Lambert over that length. A
  // thin-walled material (thickness 0) has no volume. Nested volumes are not tracked.
  out.material = p.material;
  out.signalled = false;  // the caller's to set (passSignal)
  out.inside = shading::hasVolumeAttenuation(scene_.material(p.material)) &&
               glm::dot(direction, p.faceNormal) < 0.f;
  // In place (copy elision), not assigned: copying the returned Ray reloaded its just-stored
  // floats as one 16-byte load, a store-forwarding stall per ray (perf annotate).
  static_assert(std::is_trivially_destructible_v<Ray>);
  ::new (static_cast<void*>(&out.ray)) Ray(spawnRay(p, direction));
  out.depth = depth + 1;
  return true;
}

vec3 WhittedTracer::attenuated(const SecondaryRay& s, const vec3& radiance, float distance) const {
  if (!s.inside) return radiance;
  const Material& m = scene_.material(s.material);
  return radiance *
         shading::volumeTransmittance(m.attenuationColor, m.attenuationDistance, distance);
}

vec3 WhittedTracer::traced(const SecondaryRay& s) const {
  float distance = 0.f;
  const vec3 l = radiance(s.ray, s.depth, s.seed, s.hasCone ? &s.cone : nullptr,
                          s.inside ? &distance : nullptr, s.signalled ? &s.textureSignal : nullptr,
                          s.signalled ? &s.forward : nullptr);
  return attenuated(s, l, distance);
}

void WhittedTracer::passSignal(const SecondarySignals& signals, bool reflection,
                               SecondaryRay& ray) {
  const vec4& signal = reflection ? signals.reflection : signals.transmission;
  const int hops = reflection ? signals.reflectionHops : signals.transmissionHops;
  if (signal.w < 0.f) return;
  ray.signalled = true;
  ray.textureSignal = vec4(-1.f);
  ray.forward = {};
  if (hops <= 0) {
    ray.textureSignal = signal;
  } else if (reflection) {
    ray.forward.reflection = signal;
    ray.forward.reflectionHops = hops - 1;
  } else {
    ray.forward.transmission = signal;
    ray.forward.transmissionHops = hops - 1;
  }
}

vec3 WhittedTracer::reflected(const SurfacePoint& p, const vec3& v, int depth, std::uint32_t seed,
                              const RayCone* cone, const SecondarySignals* signals) const {
  SecondaryRay s;
  if (!secondaryRay(p, v, depth, seed, cone, true, s)) return vec3(0.f);
  if (signals) passSignal(*signals, true, s);
  return traced(s);
}

vec3 WhittedTracer::transmitted(const SurfacePoint& p, const vec3& v, int depth, std::uint32_t seed,
                                const RayCone* cone, const SecondarySignals* signals) const {
  SecondaryRay s;
  if (!secondaryRay(p, v, depth, seed, cone, false, s)) return vec3(0.f);
  if (signals) passSignal(*signals, false, s);
  return traced(s);
}

}  // namespace diptych
