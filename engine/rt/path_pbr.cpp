#include "engine/rt/path_pbr.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/rt/light_sampling.h"
#include "engine/scene/camera_math.h"

namespace diptych {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float luminance(const vec3& c) {
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

// GGX half vector about n with pdf D(n.h) n.h (Walter et al. 2007, eq. 35):
// cos^2(theta_h) = (1 - u) / (1 + (a^2 - 1) u).
vec3 sampleGgxHalf(const vec3& n, float a, vec2 u) {
  const float cos2 = (1.f - u.x) / (1.f + (a * a - 1.f) * u.x);
  return directionAbout(n, std::sqrt(std::clamp(cos2, 0.f, 1.f)), 2.f * kPi * u.y);
}

}  // namespace

PbrScatter samplePbr(const shading::ShadingMaterial& m, const vec3& n, const vec3& v, float eta,
                     float uLobe, vec2 u) {
  PbrScatter s;
  const shading::SecondaryWeights sw = shading::pbrSecondaryWeights(m, n, v);
  // Albedo estimates for the lobe choice only (any positive split is unbiased).
  const float nv = std::clamp(glm::dot(n, v), 1e-4f, 1.f);
  const vec2 ab = shading::pbrEnvironmentBrdf(nv, m.roughness);
  const vec3 base = glm::clamp(m.baseColor, vec3(0.f), vec3(1.f));
  const float metallic = std::clamp(m.metallic, 0.f, 1.f);
  const vec3 f0 = glm::mix(shading::pbrDielectricF0(m) * m.specularWeight, base, metallic);
  const float spec = luminance(f0 * ab.x + vec3(ab.y));
  const float diff =
      (1.f - metallic) * (1.f - std::clamp(m.transmission, 0.f, 1.f)) * luminance(base);
  const float trans = luminance(sw.transmission);
  const float total = spec + diff + trans;
  if (!(total > 0.f)) return s;
  const float pTrans = trans / total;
  if (uLobe < pTrans) {
    s.direction = shading::refractLecture(v, n, eta).t;
    s.weight = sw.transmission / pTrans;
    s.delta = s.valid = true;
    return s;
  }
  // The reflection lobes: choose the strategy with u.x rescaled, reuse it as a fresh number.
  const float pGgx = spec + diff > 0.f ? std::clamp(spec / (spec + diff), 0.1f, 1.f) : 1.f;
  const float a = shading::pbrAlpha(m.roughness);
  vec2 w = u;
  if (w.x < pGgx) {
    w.x /= pGgx;
    const vec3 h = sampleGgxHalf(n, a, w);
    s.direction = 2.f * glm::dot(v, h) * h - v;
  } else {
    w.x = (w.x - pGgx) / (1.f - pGgx);
    s.direction = sampleCosine(n, w);
  }
  const float nl = glm::dot(n, s.direction);
  if (!(nl > 0.f)) return s;  // below the shading hemisphere: no light arrives from there
  // The half vector and D exactly as pbrDirect forms them: near a sharp peak (a = 1e-3) D is
  // ill-conditioned (a last-bit change of n.h moves it by ~10 %), and the estimator f / pdf is
  // only unbiased if numerator and pdf see the same rounded D.
  const vec3 N = shading::safeNormalize(n), V = shading::safeNormalize(v);
  const vec3 H = shading::safeNormalize(shading::safeNormalize(s.direction) + V);
  const float nh = glm::dot(N, H), vh = glm::dot(V, H);
  const float pdfGgx = vh > 0.f ? shading::pbrD(nh, a) * shading::saturate01(nh) / (4.f * vh) : 0.f;
  const float pdf = pGgx * pdfGgx + (1.f - pGgx) * nl / kPi;
  if (!(pdf > 0.f)) return s;
  // pbrDirect is pi f n.l (the shading's light units), so f n.l = pbrDirect / pi.
  const vec3 fcos = shading::pbrDirect(m, n, v, s.direction) / kPi;
  s.weight = fcos / (pdf * (1.f - pTrans));
  s.valid = std::isfinite(s.weight.x) && std::isfinite(s.weight.y) && std::isfinite(s.weight.z);
  return s;
}

}  // namespace diptych
