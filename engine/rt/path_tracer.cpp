#include "engine/rt/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "engine/rt/camera_rays.h"
#include "engine/rt/light_sampling.h"
#include "engine/rt/path_pbr.h"
#include "engine/rt/ray_cone.h"
#include "engine/rt/shadow_rays.h"
#include "engine/scene/environment.h"
#include "engine/shading/shading.h"

namespace diptych {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float maxComponent(const vec3& c) {
  return std::max(c.x, std::max(c.y, c.z));
}

// Lobe selection weights: the luminance of each lobe's albedo at normal incidence (Rec. 709),
// so that bright lobes are sampled more often. The estimator divides by the probability, so
// any positive weighting is unbiased; this one keeps the path weights near 1.
float luminance(const vec3& c) {
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

enum Lobe { kDiffuse, kGlossy, kMirror, kTransmit, kLobes };

// Selection weights of the four lobes and the chosen one.
struct LobeChoice {
  Lobe lobe = kDiffuse;
  float probability = 0.f;  // 0: the material scatters nothing
};

LobeChoice chooseLobe(const shading::ShadingMaterial& m, float u) {
  const float w[kLobes] = {m.kd * luminance(m.color), m.ks * luminance(m.specularColor),
                           m.kps * luminance(m.mirrorColor), m.kt * luminance(m.transmitColor)};
  float total = 0.f;
  for (float x : w) total += std::max(x, 0.f);
  if (!(total > 0.f)) return {};
  // Walk the cumulative weights; the last positive lobe absorbs rounding of u * total.
  float pick = u * total;
  LobeChoice c;
  for (int i = 0; i < kLobes; ++i) {
    if (!(w[i] > 0.f)) continue;
    c = {Lobe(i), w[i] / total};
    if (pick < w[i]) break;
    pick -= w[i];
  }
  return c;
}

// Phong exponent e of the material, with the shading model's convention that e < 0 means 0.
float phongExponent(const shading::ShadingMaterial& m) {
  return std::max(m.exponent, 0.f);
}

// Direct light from a scene light per unit of S_i, by the material's model (the glTF model's
// pi f n.l, or) DIRECTA without k_a,
// k_d C max(0, n.l) + k_s d_i max(0, r.v)^e per unit of S_i. The lecture's lights deliver S_i
// into this term with no 1/pi, so next-event estimation uses it (and not f cos) to make the
// path-traced reference equal the Whitted one wherever there is no indirect light; the
// energy-conserving BRDF above governs the bounces.
vec3 lectureDirect(shading::ShadingMaterial m, const vec3& n, const vec3& v, const vec3& l) {
  m.ka = 0.f;  // ambient is what global illumination replaces
  return shading::directResponse(m, n, v, l);
}

// Direction about `axis` with pdf (e + 1) / (2 pi) cos^e(alpha) per steradian: e = 0 is the
// uniform hemisphere, e -> infinity the axis itself (Lafortune and Willems 1994).
vec3 samplePowerCosine(const vec3& axis, float e, vec2 u) {
  return directionAbout(axis, std::pow(u.x, 1.f / (e + 1.f)), 2.f * kPi * u.y);
}

// The area-light pdf of areaLightPoint(): uniform over the quad or disc (1 / area) and over
// the hemisphere of the sphere that faces the receiver (1 / (2 pi r^2)). Returns the area.
float samplingArea(const Light& light) {
  switch (light.type) {
    case LightType::QuadArea:
      return glm::length(glm::cross(light.edgeU, light.edgeV));
    case LightType::DiscArea:
      return kPi * light.radius * light.radius;
    case LightType::SphereArea:
      return 2.f * kPi * light.radius * light.radius;
    default:
      return 0.f;
  }
}

bool visible(const RtScene& rt, const OcclusionRay& r, std::uint32_t& rays) {
  if (r.tnear > r.tfar) return true;  // inactive: castsShadows == false or degenerate
  ++rays;
  return !rt.occluded(r.origin, r.direction, r.tnear, r.tfar);
}

bool finite(const vec3& c) {
  return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z);
}

}  // namespace

PathRng::PathRng(std::uint32_t pixel, std::uint32_t sample, std::uint32_t seed)
    : state_(pcgHash(pcgHash(pcgHash(seed) + pixel) + sample)) {}

float PathRng::next() {
  // pcgHash(s) is the PCG-RXS-M-XS output of the LCG successor of s; advancing s by the same
  // LCG step makes the outputs one PCG stream.
  const std::uint32_t out = pcgHash(state_);
  state_ = state_ * 747796405u + 2891336453u;
  return float(out >> 8) * (1.f / 16777216.f);  // 24 bits: exact, never 1
}

PathTracer::PathTracer(const Scene& scene, const WorldGeometry& world, const RtScene& rt,
                       PathSettings settings)
    : scene_(scene), world_(world), rt_(rt), settings_(settings) {
  for (const Light& light : scene.lights) lights_.push_back(shading::toShadingLight(light));
}

vec3 PathTracer::nextEvent(const SurfacePoint& p, const vec3& v, PathRng& rng,
                           std::uint32_t& rays) const {
  const shading::ShadingMaterial& m = p.resolved;
  const bool lecture = m.model != shading::SHADING_MODEL_GLTF;
  if (lecture && !(m.kd > 0.f) && !(m.ks > 0.f)) return vec3(0.f);  // delta lobes only
  const vec3& n = p.shadingNormal;
  const ShadowReceiver receiver{p.position, p.faceNormal, p.positionMagnitude};
  vec3 sum(0.f);
  for (std::size_t i = 0; i < lights_.size(); ++i) {
    const Light& light = scene_.lights[i];
    if (!isAreaLight(light)) {
      // Delta lights: S_i as in the shading model (point and spot I / d^2 with the cone
      // factor, directional E), so L = DIRECTA(l) S V.
      const shading::LightSample s = shading::sampleLight(lights_[i], p.position);
      const vec3 direct = lectureDirect(m, n, v, s.l);
      if (s.radiance == vec3(0.f) || direct == vec3(0.f)) continue;
      if (visible(rt_, makeShadowRay(light, receiver), rays)) sum += direct * s.radiance;
      continue;
    }
    // Area lights: one point y with area pdf 1/A; the solid-angle pdf is d^2 / (A cos_y), so
    // L = DIRECTA(l) L_e cos_y A / d^2 V. Same hard range cut-off as the shading model.
    if (light.range > 0.f && glm::distance(light.position, p.position) > light.range) continue;
    const vec3 y = areaLightPoint(light, rng.next2(), p.position);
    const vec3 toLight = y - p.position;
    const float d2 = glm::dot(toLight, toLight);
    if (!(d2 > 0.f)) continue;
    const vec3 l = toLight / std::sqrt(d2);
    const vec3 emitterNormal = light.type == LightType::SphereArea
                                   ? glm::normalize(y - light.position)
                                   : glm::normalize(light.direction);  // one-sided emitters
    const float cosLight = glm::dot(emitterNormal, -l);
    const vec3 direct = lectureDirect(m, n, v, l);
    if (!(cosLight > 0.f) || direct == vec3(0.f)) continue;
    if (!visible(rt_, makeShadowRayTo(light, receiver, y), rays)) continue;
    const vec3 emitted = light.color * std::max(light.intensity, 0.f);
    sum += direct * emitted * (cosLight * samplingArea(light) / d2);
  }
  return sum;
}

PathSample PathTracer::radiance(const Ray& cameraRay, PathRng& rng, float coneSpread) const {
  // Depth 1 is the camera ray: it does not see back faces of single-sided materials.
  Hit first;
  const bool found = CameraRays{rt_, scene_, world_}.intersect(cameraRay, first, false);
  return radiance(cameraRay, found ? &first : nullptr, rng, coneSpread);
}

PathSample PathTracer::radiance(const Ray& cameraRay, const Hit* firstHit, PathRng& rng,
                                float coneSpread) const {
  PathSample out;
  vec3 throughput(1.f);
  Ray ray = cameraRay;
  const Material* medium = nullptr;  // the volume the current segment runs inside, if any
  bool coneLive = settings_.rayCones;
  RayCone cone{0.f, coneSpread};
  for (int depth = 1;; ++depth) {
    ++out.rays;
    Hit traced;
    const Hit* hit =
        depth == 1                                                                       ? firstHit
        : rt_.intersect(ray, 0.f, std::numeric_limits<float>::infinity(), traced, false) ? &traced
                                                                                         : nullptr;
    if (medium)  // KHR_materials_volume: Beer-Lambert over the segment (as the Whitted tracer)
      throughput *= shading::volumeTransmittance(
          medium->attenuationColor, medium->attenuationDistance,
          hit ? hit->t * glm::length(ray.direction) : std::numeric_limits<float>::infinity());
    if (!hit) {
      out.radiance += throughput * sampleEnvironment(scene_.environment, ray.direction);
      break;
    }
    SurfacePoint p = makeSurfacePoint(
        scene_, world_, {hit->instance, hit->primitive, hit->u, hit->v, hit->analytic},
        ray.direction);
    if (coneLive) {  // RTG eq. 20.23 at the cone's width here, as WhittedTracer::radiance
      cone.width += cone.spread * hit->t * glm::length(ray.direction);
      p.resolved = resolveMaterial(scene_, scene_.material(p.material), p.uv,
                                   coneUvLod(world_, p, ray.direction, cone.width));
    }
    const shading::ShadingMaterial& m = p.resolved;
    const vec3 v = -ray.direction;
    out.radiance += throughput * (m.emission + nextEvent(p, v, rng, out.rays));
    if (depth >= settings_.maxDepth) break;

    vec3 direction, weight;
    bool smoothLobe = true;
    if (m.model == shading::SHADING_MODEL_GLTF) {  // the glTF model's own sampling (path_pbr.h)
      const float ior = scene_.material(p.material).ior;
      const float uLobe = rng.next();
      const PbrScatter s =
          samplePbr(m, p.shadingNormal, v, p.frontFacing ? 1.f / ior : ior, uLobe, rng.next2());
      if (!s.valid) break;
      direction = s.direction;
      weight = s.weight;
      smoothLobe = !s.delta;
    } else {
      // Scatter: pick one lobe with probability weight / total and divide by it.
      const LobeChoice choice = chooseLobe(m, rng.next());
      if (!(choice.probability > 0.f)) break;
      const vec3& n = p.shadingNormal;
      const vec2 u = rng.next2();
      switch (choice.lobe) {
        case kDiffuse:  // f cos / pdf = (k_d C / pi) cos / (cos / pi)
          direction = sampleCosine(n, u);
          weight = m.kd * m.color;
          break;
        case kGlossy: {  // f cos / pdf = k_s d (e + 2) / (e + 1) cos(theta): cos^e cancels
          const float e = phongExponent(m);
          direction = samplePowerCosine(glm::normalize(shading::reflectAbout(v, n)), e, u);
          weight = m.ks * m.specularColor *
                   ((e + 2.f) / (e + 1.f) * std::max(0.f, glm::dot(n, direction)));
          break;
        }
        case kMirror:
          direction = glm::normalize(shading::reflectAbout(v, n));
          weight = m.kps * m.mirrorColor;
          break;
        default: {  // as in the Whitted tracer: air outside, ior inside, told apart by the face
          const float ior = scene_.material(p.material).ior;
          direction = shading::refractLecture(v, n, p.frontFacing ? 1.f / ior : ior).t;
          weight = m.kt * m.transmitColor;
          break;
        }
      }
      weight /= choice.probability;
      smoothLobe = choice.lobe == kDiffuse || choice.lobe == kGlossy;
    }
    // A smooth lobe is sampled about the shading normal and may point into the geometry: no
    // light arrives from there, and tracing it would leak through the surface.
    if (smoothLobe && !(glm::dot(direction, p.geometricNormal) > 0.f)) break;
    if (coneLive && smoothLobe) coneLive = false;
    // A delta bounce on the viewer's side is a reflection (its spread grows with curvature),
    // one through the surface a refraction (unchanged, as in WhittedTracer).
    if (coneLive && glm::dot(direction, p.geometricNormal) * glm::dot(v, p.geometricNormal) > 0.f)
      cone = reflectedCone(world_, p, cone.width, cone.spread);
    throughput *= weight;
    if (!finite(throughput) || throughput == vec3(0.f)) break;
    ray = spawnRay(p, direction);
    // Into the back side of the (outward) face: inside the material's volume.
    const Material& mat = scene_.material(p.material);
    medium = shading::hasVolumeAttenuation(mat) && glm::dot(direction, p.faceNormal) < 0.f
                 ? &mat
                 : nullptr;

    if (settings_.russianRoulette && depth >= settings_.rrDepth) {
      const float survive = std::min(1.f, maxComponent(throughput));
      if (rng.next() >= survive) break;
      throughput /= survive;
    }
  }
  if (!finite(out.radiance)) {  // never expected; reported by the pass rather than averaged
    out.radiance = vec3(0.f);
    out.valid = false;
  }
  return out;
}

}  // namespace diptych
