#include "engine/shading/bump.h"

#include <cmath>

#include "engine/shading/texture_sampling.h"

namespace diptych {

vec3 bumpNormalFromTexture(const Texture& height, vec2 uv, float k, float delta, const vec3& tu,
                           const vec3& tv, const vec3& n) {
  const auto f = [&](vec2 at) {
    return sampleBilinear(height.image, at, height.wrapS, height.wrapT).x;
  };
  const float du = shading::bumpSlope(f(uv + vec2(delta, 0.f)), f(uv - vec2(delta, 0.f)), k, delta);
  const float dv = shading::bumpSlope(f(uv + vec2(0.f, delta)), f(uv - vec2(0.f, delta)), k, delta);
  return shading::bumpNormal(tu, tv, n, du, dv);
}

float bumpSinusoid(const BumpMap& bump, vec2 uv) {
  constexpr float kTwoPi = 6.28318530717959f;
  return bump.amplitude * std::sin(kTwoPi * bump.frequency.x * uv.x) *
         std::cos(kTwoPi * bump.frequency.y * uv.y);
}

vec3 bumpMapNormal(const Scene& scene, const BumpMap& bump, vec2 uv, const vec3& tu, const vec3& tv,
                   const vec3& n) {
  if (bump.texture >= 0) {
    if (bump.texture >= int(scene.textures.size())) return shading::safeNormalize(n);
    return bumpNormalFromTexture(scene.textures[std::size_t(bump.texture)], uv, bump.k, bump.delta,
                                 tu, tv, n);
  }
  const float d = bump.delta;
  const float du = shading::bumpSlope(bumpSinusoid(bump, uv + vec2(d, 0.f)),
                                      bumpSinusoid(bump, uv - vec2(d, 0.f)), bump.k, d);
  const float dv = shading::bumpSlope(bumpSinusoid(bump, uv + vec2(0.f, d)),
                                      bumpSinusoid(bump, uv - vec2(0.f, d)), bump.k, d);
  return shading::bumpNormal(tu, tv, n, du, dv);
}

SurfaceTangents triangleTangents(const vec3& p0, const vec3& p1, const vec3& p2, vec2 uv0, vec2 uv1,
                                 vec2 uv2) {
  const vec3 e1 = p1 - p0, e2 = p2 - p0;
  const vec2 d1 = uv1 - uv0, d2 = uv2 - uv0;
  const float det = d1.x * d2.y - d2.x * d1.y;
  if (!(std::abs(det) > 0.f) || !std::isfinite(det)) return {};
  const float r = 1.f / det;
  return {(e1 * d2.y - e2 * d1.y) * r, (e2 * d1.x - e1 * d2.x) * r};
}

}  // namespace diptych
