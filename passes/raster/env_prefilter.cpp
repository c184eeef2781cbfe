#include "passes/raster/env_prefilter.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/rt/light_sampling.h"
#include "engine/scene/environment.h"
#include "passes/raster/env_maps.h"

namespace diptych::envmap {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr int kSamples = 64;  // per texel; filtered importance sampling keeps 64 smooth

// Hammersley point k of n (van der Corput radical inverse in base 2).
vec2 hammersley(unsigned k, unsigned n) {
  unsigned bits = k;
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return vec2(float(k) / float(n), float(bits) * 2.3283064365386963e-10f);
}

// Bilinear at (s, t) in [0,1]^2 of an RGB image, clamped to its edges.
vec3 bilinear(const Image& img, vec2 st) {
  const float fx = st.x * float(img.width) - 0.5f, fy = st.y * float(img.height) - 0.5f;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const float ax = fx - float(x0), ay = fy - float(y0);
  auto texel = [&](int x, int y) {
    x = std::clamp(x, 0, img.width - 1);
    y = std::clamp(y, 0, img.height - 1);
    return vec3(img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2));
  };
  return glm::mix(glm::mix(texel(x0, y0), texel(x0 + 1, y0), ax),
                  glm::mix(texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), ax), ay);
}

// 2x2 box average: a side s image becomes side max(1, s / 2).
Image halve(const Image& in) {
  const int w = std::max(1, in.width / 2), h = std::max(1, in.height / 2);
  Image out(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < 3; ++k) {
        float sum = 0.f;
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 2; ++i)
            sum += in.at(std::min(2 * x + i, in.width - 1), std::min(2 * y + j, in.height - 1), k);
        out.at(x, y, k) = 0.25f * sum;
      }
  return out;
}

}  // namespace

int prefilterLevelCount(int width, int height) {
  int levels = 1;
  for (int side = std::min(width, height); levels < 6 && side / 2 >= 4; side /= 2) ++levels;
  return levels;
}

CubeChain::CubeChain(const Environment& env, int size) : size_(std::max(size, 1)) {
  // Level 0 is the 2x2 box average of a map twice the size, so that a sharp source (a sun
  // disc) is area-sampled rather than point-sampled.
  std::array<Image, 6> fine = cubeFacesFrom(env, 2 * size_);
  std::array<Image, 6> level;
  for (int f = 0; f < 6; ++f) {
    Image rgb(fine[f].width, fine[f].height, 3);
    for (int y = 0; y < rgb.height; ++y)
      for (int x = 0; x < rgb.width; ++x)
        for (int k = 0; k < 3; ++k) rgb.at(x, y, k) = fine[f].at(x, y, k);
    level[f] = halve(rgb);
  }
  levels_.push_back(level);
  while (levels_.back()[0].width > 1) {
    std::array<Image, 6> next;
    for (int f = 0; f < 6; ++f) next[f] = halve(levels_.back()[f]);
    levels_.push_back(std::move(next));
  }
}

vec3 CubeChain::sampleLevel(int level, int face, vec2 st) const {
  return bilinear(levels_[std::size_t(level)][std::size_t(face)], st);
}

vec3 CubeChain::sample(const vec3& direction, float lod) const {
  vec2 st;
  const int face = cubeFace(direction, st);
  const float top = float(levels_.size() - 1);
  lod = std::clamp(lod, 0.f, top);
  const int l0 = int(std::floor(lod));
  const int l1 = std::min(l0 + 1, int(top));
  return glm::mix(sampleLevel(l0, face, st), sampleLevel(l1, face, st), lod - float(l0));
}

Image prefilteredLevel(const CubeChain& source, int width, int height, float roughness,
                       const std::function<vec3(vec2)>& direction) {
  // GGX alpha as pbr.glsl's pbrAlpha (roughness^2, floored at 1e-3).
  const float a = std::max(roughness * roughness, 1e-3f), a2 = a * a;
  // Solid angle of one level-0 texel of the source cube (4 pi over 6 size^2 texels).
  const float texelSolidAngle = 4.f * kPi / (6.f * float(source.size()) * float(source.size()));
  Image out(width, height, 4, 1.f);
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const vec3 n = glm::normalize(
          direction(vec2((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height))));
      vec3 t, b;
      orthonormalBasis(n, t, b);
      vec3 sum(0.f);
      float weight = 0.f;
      for (int k = 0; k < kSamples; ++k) {
        // GGX half vector (Walter et al. 2007, eq. 35): cos^2 = (1 - u) / (1 + (a^2 - 1) u).
        const vec2 u = hammersley(unsigned(k), unsigned(kSamples));
        const float cos2 = (1.f - u.x) / (1.f + (a2 - 1.f) * u.x);
        const float cosT = std::sqrt(std::clamp(cos2, 0.f, 1.f));
        const float sinT = std::sqrt(std::max(0.f, 1.f - cosT * cosT));
        const float phi = 2.f * kPi * u.y;
        const vec3 h = cosT * n + sinT * (std::cos(phi) * t + std::sin(phi) * b);
        const vec3 l = 2.f * cosT * h - n;  // v = n, so v.h = n.h = cosT
        const float nl = glm::dot(n, l);
        if (!(nl > 0.f)) continue;
        // pdf of l with v = n: D(n.h) n.h / (4 v.h) = D / 4; the sample's solid angle
        // 1 / (N pdf) picks the source level (Colbert and Krivanek 2007, eq. 13, +1 bias).
        const float d = cos2 * (a2 - 1.f) + 1.f;
        const float pdf = a2 / (kPi * d * d) / 4.f;
        const float sampleSolidAngle = 1.f / (float(kSamples) * pdf);
        const float lod = 0.5f * std::log2(sampleSolidAngle / texelSolidAngle) + 1.f;
        sum += source.sample(l, lod) * nl;
        weight += nl;
      }
      const vec3 c = weight > 0.f ? sum / weight : vec3(0.f);
      for (int k = 0; k < 3; ++k) out.at(x, y, k) = c[k];
    }
  });
  return out;
}

vec3 PrefilteredCube::sample(int level, const vec3& direction) const {
  vec2 st;
  const int face = cubeFace(direction, st);
  return bilinear(levels[std::size_t(level)][std::size_t(face)], st);
}

PrefilteredCube prefilteredCube(const CubeChain& source, const std::vector<int>& faceSides) {
  PrefilteredCube cube;
  const int count = int(faceSides.size());
  cube.levels.resize(faceSides.size());
  for (int level = 1; level < count; ++level) {
    const float roughness = float(level) / float(count - 1);
    const int side = std::max(1, faceSides[std::size_t(level)]);
    for (int f = 0; f < 6; ++f) {
      const Image rgba = prefilteredLevel(source, side, side, roughness,
                                          [f](vec2 st) { return cubeFaceDirection(f, st); });
      Image rgb(side, side, 3);
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
          for (int k = 0; k < 3; ++k) rgb.at(x, y, k) = rgba.at(x, y, k);
      cube.levels[std::size_t(level)][std::size_t(f)] = std::move(rgb);
    }
  }
  return cube;
}

Image resampledLevel(const PrefilteredCube& cube, int level, int width, int height,
                     const std::function<vec3(vec2)>& direction) {
  Image out(width, height, 4, 1.f);
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const vec3 c =
          cube.sample(level, glm::normalize(direction(vec2((float(x) + 0.5f) / float(width),
                                                           (float(y) + 0.5f) / float(height)))));
      for (int k = 0; k < 3; ++k) out.at(x, y, k) = c[k];
    }
  });
  return out;
}

}  // namespace diptych::envmap
