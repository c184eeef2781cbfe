#include "engine/rt/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <new>
#include <numbers>

#include "engine/core/check.h"
#include "engine/rt/camera_rays.h"
#include "engine/rt/light_sampling.h"
#include "engine/rt/occlusion_stream.h"
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
  return unitFloat(out);
}

PathTracer::PathTracer(const Scene& scene, const WorldGeometry& world, const RtScene& rt,
                       PathSettings settings)
    : scene_(scene), world_(world), rt_(rt), settings_(settings) {
  for (const Light& light : scene.lights) lights_.push_back(shading::toShadingLight(light));
}

// A light's next-event term at one path vertex.
struct PathTracer::LightTerm {
  vec3 contribution{0.f};
  bool lit = false;  // formed, and its shadow ray (if any) unoccluded
};

// The shadow rays of a level of paths, traced as Embree streams (OcclusionStream). A ray's
// owner is its term's `lit`, which an occluded ray clears.
struct ClearIfOccluded {
  void operator()(bool* lit, bool visible) const {
    if (!visible) *lit = false;
  }
};
class PathTracer::ShadowStream : public OcclusionStream<bool*, ClearIfOccluded> {
 public:
  ShadowStream(const RtScene& rt, bool coherent) : OcclusionStream(rt, coherent, {}) {}
};

void PathTracer::nextEventTerms(const SurfacePoint& p, const vec3& v, PathRng& rng,
                                LightTerm* terms, std::uint32_t& rays, ShadowStream& shadow) const {
  const shading::ShadingMaterial& m = p.resolved;
  const bool lecture = m.model != shading::SHADING_MODEL_GLTF;
  if (lecture && !(m.kd > 0.f) && !(m.ks > 0.f)) return;  // delta lobes only
  const vec3& n = p.shadingNormal;
  const ShadowReceiver receiver{p.position, p.faceNormal, p.positionMagnitude, p.time};
  // The term is lit unless its shadow ray is traced and occluded; an inactive ray
  // (castsShadows false, or degenerate) is not traced and lets the term through.
  const auto formed = [&](LightTerm& term, const vec3& contribution, const OcclusionRay& r) {
    term.contribution = contribution;
    term.lit = true;
    if (r.tnear > r.tfar) return;
    ++rays;
    shadow.add(r, &term.lit);
  };
  for (std::size_t i = 0; i < lights_.size(); ++i) {
    const Light& light = scene_.lights[i];
    if (!isAreaLight(light)) {
      // Delta lights: S_i as in the shading model (point and spot I / d^2 with the cone
      // factor, directional E), so L = DIRECTA(l) S V.
      const shading::LightSample s = shading::sampleLight(lights_[i], p.position);
      const vec3 direct = lectureDirect(m, n, v, s.l);
      if (s.radiance == vec3(0.f) || direct == vec3(0.f)) continue;
      formed(terms[i], direct * s.radiance, makeShadowRay(light, receiver));
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
    const vec3 emitted = light.color * std::max(light.intensity, 0.f);
    formed(terms[i], direct * emitted * (cosLight * samplingArea(light) / d2),
           makeShadowRayTo(light, receiver, y));
  }
}

PathSample PathTracer::radiance(const Ray& cameraRay, PathRng& rng, float coneSpread) const {
  // Depth 1 is the camera ray: it does not see back faces of single-sided materials.
  Hit first;
  const Hit* found =
      CameraRays{rt_, scene_, world_}.intersect(cameraRay, first, false) ? &first : nullptr;
  PathSample out;
  radiance({&cameraRay, 1}, {&found, 1}, {&rng, 1}, coneSpread, {&out, 1});
  return out;
}

// One path between its vertices.
struct PathTracer::PathState {
  Ray ray;
  vec3 throughput{1.f};
  const Material* medium = nullptr;  // the volume the current segment runs inside, if any
  RayCone cone;
  bool coneLive = false;
  bool live = true;
};

bool PathTracer::scatter(const SurfacePoint& p, int depth, PathRng& rng, PathState& path) const {
  if (depth >= settings_.maxDepth) return false;
  const shading::ShadingMaterial& m = p.resolved;
  const vec3 v = -path.ray.direction;
  vec3 direction, weight;
  bool smoothLobe = true;
  if (m.model == shading::SHADING_MODEL_GLTF) {  // the glTF model's own sampling (path_pbr.h)
    const float ior = scene_.material(p.material).ior;
    const float uLobe = rng.next();
    const PbrScatter s =
        samplePbr(m, p.shadingNormal, v, p.frontFacing ? 1.f / ior : ior, uLobe, rng.next2());
    if (!s.valid) return false;
    direction = s.direction;
    weight = s.weight;
    smoothLobe = !s.delta;
  } else {
    // Scatter: pick one lobe with probability weight / total and divide by it.
    const LobeChoice choice = chooseLobe(m, rng.next());
    if (!(choice.probability > 0.f)) return false;
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
  if (smoothLobe && !(glm::dot(direction, p.geometricNormal) > 0.f)) return false;
  if (path.coneLive && smoothLobe) path.coneLive = false;
  // A delta bounce on the viewer's side is a reflection (its spread grows with curvature),
  // one through the surface a refraction (unchanged, as in WhittedTracer).
  if (path.coneLive &&
      glm::dot(direction, p.geometricNormal) * glm::dot(v, p.geometricNormal) > 0.f)
    path.cone = reflectedCone(world_, p, path.cone.width, path.cone.spread);
  path.throughput *= weight;
  if (!finite(path.throughput) || path.throughput == vec3(0.f)) return false;
  path.ray = spawnRay(p, direction);
  // Into the back side of the (outward) face: inside the material's volume.
  const Material& mat = scene_.material(p.material);
  path.medium = shading::hasVolumeAttenuation(mat) && glm::dot(direction, p.faceNormal) < 0.f
                    ? &mat
                    : nullptr;
  if (settings_.russianRoulette && depth >= settings_.rrDepth) {
    const float survive = std::min(1.f, maxComponent(path.throughput));
    if (rng.next() >= survive) return false;
    path.throughput /= survive;
  }
  return true;
}

void PathTracer::radiance(std::span<const Ray> cameraRays, std::span<const Hit* const> firstHits,
                          std::span<PathRng> rngs, float coneSpread,
                          std::span<PathSample> out) const {
  const std::size_t n = cameraRays.size(), lights = lights_.size();
  DIPTYCH_CHECK(n <= kMaxPaths && firstHits.size() == n && rngs.size() == n && out.size() >= n,
                "PathTracer::radiance: chunk sizes disagree");
  PathState paths[kMaxPaths];
  for (std::size_t i = 0; i < n; ++i) {
    paths[i].ray = cameraRays[i];
    paths[i].coneLive = settings_.rayCones;
    paths[i].cone = RayCone{0.f, coneSpread};
    out[i] = PathSample{};
  }
  // Per thread, reused level after level: no allocation per vertex. Nothing between a level's
  // fill and its last read enters TBB (surface points, light sampling, Embree streams), so no
  // other chunk's radiance() can run on this thread meanwhile and reuse it (as radianceTile's
  // scratch).
  thread_local std::vector<LightTerm> terms;
  // Raw storage, each vertex's point constructed in place: an array of SurfacePoint would run
  // its member initialisers over ~62 KB per level first. About 135 KB of stack in all, once
  // per chunk (no recursion), well inside TBB's 4 MB worker stacks.
  alignas(SurfacePoint) std::byte pointStorage[kMaxPaths * sizeof(SurfacePoint)];
  const auto point = [&](std::size_t i) {
    return std::launder(reinterpret_cast<SurfacePoint*>(pointStorage) + i);
  };
  Ray rays[kMaxPaths];
  Hit traced[kMaxPaths];
  const Hit* hits[kMaxPaths];
  std::size_t slot[kMaxPaths];  // the live paths of this level
  for (int depth = 1;; ++depth) {
    std::size_t live = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (paths[i].live) slot[live++] = i;
    if (live == 0) break;
    // The level's closest hits: the camera rays' are given; later bounces scatter, so their
    // stream is traced incoherent.
    if (depth == 1) {
      for (std::size_t k = 0; k < live; ++k) hits[k] = firstHits[slot[k]];
    } else {
      for (std::size_t k = 0; k < live; ++k) rays[k] = paths[slot[k]].ray;
      rt_.intersectRays({rays, live}, {traced, live}, {hits, live}, false, false);
    }
    terms.assign(live * lights, LightTerm{});
    ShadowStream shadow(rt_, depth == 1);
    for (std::size_t k = 0; k < live; ++k) {
      PathState& path = paths[slot[k]];
      PathSample& o = out[slot[k]];
      const Ray& ray = path.ray;
      const Hit* hit = hits[k];
      ++o.rays;
      if (path.medium)  // KHR_materials_volume: Beer-Lambert over the segment (as Whitted)
        path.throughput *= shading::volumeTransmittance(
            path.medium->attenuationColor, path.medium->attenuationDistance,
            hit ? hit->t * glm::length(ray.direction) : std::numeric_limits<float>::infinity());
      if (!hit) {
        o.radiance += path.throughput * sampleEnvironment(scene_.environment, ray.direction);
        path.live = false;
        continue;
      }
      SurfacePoint& p = *::new (static_cast<void*>(point(k))) SurfacePoint(makeSurfacePoint(
          scene_, world_, {hit->instance, hit->primitive, hit->u, hit->v, hit->analytic},
          ray.direction));
      atShutterTime(p, world_, ray.time);
      if (path.coneLive) {  // RTG eq. 20.23 at the cone's width here, as WhittedTracer::radiance
        path.cone.width += path.cone.spread * hit->t * glm::length(ray.direction);
        p.resolved = resolveMaterial(scene_, scene_.material(p.material), p.uv,
                                     coneUvLod(world_, p, ray.direction, path.cone.width));
      }
      nextEventTerms(p, -ray.direction, rngs[slot[k]], terms.data() + k * lights, o.rays, shadow);
    }
    shadow.flush();
    for (std::size_t k = 0; k < live; ++k) {
      if (!hits[k]) continue;  // ended at the environment above
      const std::size_t i = slot[k];
      const SurfacePoint& p = *point(k);
      // The unoccluded terms in light order, as one path's loop sums them.
      vec3 direct(0.f);
      for (std::size_t l = 0; l < lights; ++l)
        if (const LightTerm& t = terms[k * lights + l]; t.lit) direct += t.contribution;
      out[i].radiance += paths[i].throughput * (p.resolved.emission + direct);
      paths[i].live = scatter(p, depth, rngs[i], paths[i]);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (finite(out[i].radiance)) continue;  // never expected; reported by the pass
    out[i].radiance = vec3(0.f);
    out[i].valid = false;
  }
}

}  // namespace diptych
