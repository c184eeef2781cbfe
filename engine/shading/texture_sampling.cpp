#include "engine/shading/texture_sampling.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace diptych {
namespace {

// The texel at p of an image with `channels` channels (Image::at's layout). Textures are RGBA
// (Texture::image), so that case is one load; a grey image (a height map) repeats its channel.
inline vec4 texelAt(const float* p, int channels) {
  if (channels >= 4) return vec4(p[0], p[1], p[2], p[3]);
  if (channels == 1) return vec4(p[0], p[0], p[0], 1.f);
  vec4 c(0.f, 0.f, 0.f, 1.f);
  for (int k = 0; k < channels; ++k) c[k] = p[k];
  return c;
}

// An image's texels as one lookup reads them: the row stride and channel count are fetched once
// per lookup, each texel is then an offset into a row (issue 14's profile of
// texture_supersample: the per-texel Image::at index and channel loop were its hottest code).
struct Texels {
  const float* data;
  std::size_t rowStride;  // floats per row
  int channels;
  explicit Texels(const Image& image)
      : data(image.pixels.data()),
        rowStride(std::size_t(image.width) * std::size_t(image.channels)),
        channels(image.channels) {}
  const float* row(int y) const { return data + std::size_t(y) * rowStride; }
  vec4 at(const float* row, int x) const {
    return texelAt(row + std::size_t(x) * std::size_t(channels), channels);
  }
};

// Texel indices x0 and x0 + 1 after the wrap mode. Inside [0, size) every mode is the identity,
// so only a pair at the image's edge (or beyond it) takes wrapTexel's switch and divisions.
inline void wrapPair(int x0, int size, WrapMode mode, int& a, int& b) {
  if (x0 >= 0 && x0 < size - 1) {
    a = x0;
    b = x0 + 1;
  } else {
    a = wrapTexel(x0, size, mode);
    b = wrapTexel(x0 + 1, size, mode);
  }
}

// Reduces a texture coordinate to a small range before it is scaled and converted to int, so
// that huge or non-finite uv cannot overflow the integer conversion. The reduction is by whole
// periods of the wrap mode, which the wrap leaves unchanged.
float reduceCoordinate(float t, WrapMode mode) {
  if (!std::isfinite(t)) return 0.f;
  switch (mode) {
    case WrapMode::Repeat:
      return t - std::floor(t);  // period 1
    case WrapMode::MirroredRepeat:
      return t - 2.f * std::floor(0.5f * t);  // period 2
    case WrapMode::ClampToEdge:
      return t < -1.f ? -1.f : (t > 2.f ? 2.f : t);
  }
  return t;
}

bool isNearest(FilterMode f) {
  return f == FilterMode::Nearest || f == FilterMode::NearestMipmapNearest ||
         f == FilterMode::NearestMipmapLinear;
}

}  // namespace

int wrapTexel(int i, int size, WrapMode mode) {
  if (size <= 1) return 0;
  switch (mode) {
    case WrapMode::Repeat: {
      const int m = i % size;
      return m < 0 ? m + size : m;
    }
    case WrapMode::MirroredRepeat: {
      // Period 2 * size: the image, then its mirror image (GL's mirror(a) on texel indices).
      int m = i % (2 * size);
      if (m < 0) m += 2 * size;
      return m < size ? m : 2 * size - 1 - m;
    }
    case WrapMode::ClampToEdge:
      return i < 0 ? 0 : (i >= size ? size - 1 : i);
  }
  return 0;
}

vec4 sampleNearest(const Image& image, vec2 uv, WrapMode wrapS, WrapMode wrapT) {
  if (image.empty()) return vec4(1.f);
  const float u = reduceCoordinate(uv.x, wrapS), v = reduceCoordinate(uv.y, wrapT);
  int x = int(std::floor(u * float(image.width))), y = int(std::floor(v * float(image.height)));
  // As wrapPair: the identity inside the image.
  if (x < 0 || x >= image.width) x = wrapTexel(x, image.width, wrapS);
  if (y < 0 || y >= image.height) y = wrapTexel(y, image.height, wrapT);
  const Texels texels(image);
  return texels.at(texels.row(y), x);
}

vec4 sampleBilinear(const Image& image, vec2 uv, WrapMode wrapS, WrapMode wrapT) {
  if (image.empty()) return vec4(1.f);
  const float u = reduceCoordinate(uv.x, wrapS), v = reduceCoordinate(uv.y, wrapT);
  // Position in texel units relative to texel centres.
  const float x = u * float(image.width) - 0.5f, y = v * float(image.height) - 0.5f;
  const float x0f = std::floor(x), y0f = std::floor(y);
  const float fx = x - x0f, fy = y - y0f;
  const int x0 = int(x0f), y0 = int(y0f);
  int xa, xb, ya, yb;
  wrapPair(x0, image.width, wrapS, xa, xb);
  wrapPair(y0, image.height, wrapT, ya, yb);
  const Texels texels(image);
  const float *rowA = texels.row(ya), *rowB = texels.row(yb);
  const vec4 top = glm::mix(texels.at(rowA, xa), texels.at(rowA, xb), fx);
  const vec4 bottom = glm::mix(texels.at(rowB, xa), texels.at(rowB, xb), fx);
  return glm::mix(top, bottom, fy);
}

vec4 sampleTexture(const Texture& texture, vec2 uv, bool minifying) {
  const FilterMode f = minifying ? texture.minFilter : texture.magFilter;
  return isNearest(f) ? sampleNearest(texture.image, uv, texture.wrapS, texture.wrapT)
                      : sampleBilinear(texture.image, uv, texture.wrapS, texture.wrapT);
}

int mipLevelCount(const Texture& texture) {
  return 1 + int(texture.mips.size());
}

const Image& mipLevel(const Texture& texture, int level) {
  return level <= 0 || texture.mips.empty()
             ? texture.image
             : texture.mips[std::size_t(std::min(level, int(texture.mips.size())) - 1)];
}

vec4 sampleFiltered(const Texture& texture, vec2 uv, float lambda, bool linearTexels,
                    MipSelect mips) {
  const auto at = [&](int level) {
    const Image& image = mipLevel(texture, level);
    return linearTexels ? sampleBilinear(image, uv, texture.wrapS, texture.wrapT)
                        : sampleNearest(image, uv, texture.wrapS, texture.wrapT);
  };
  const int top = mipLevelCount(texture) - 1;
  if (mips == MipSelect::None || !(lambda > 0.f)) return at(0);  // also NaN
  const float l = std::min(lambda, float(top));
  if (mips == MipSelect::Nearest) {
    // GL 4.5 eq. 8.10: d = ceil(lambda + 1/2) - 1 for lambda > 1/2, else 0.
    return at(l > 0.5f ? int(std::ceil(l + 0.5f)) - 1 : 0);
  }
  const int d1 = int(std::floor(l));
  const float f = l - float(d1);
  if (d1 >= top || f == 0.f) return at(d1);
  return glm::mix(at(d1), at(d1 + 1), f);
}

vec4 sampleTextureLod(const Texture& texture, vec2 uv, float lambda) {
  if (!(lambda > 0.f))
    return sampleFiltered(texture, uv, 0.f, !isNearest(texture.magFilter), MipSelect::None);
  switch (texture.minFilter) {
    case FilterMode::Nearest:
      return sampleFiltered(texture, uv, lambda, false, MipSelect::None);
    case FilterMode::Linear:
      return sampleFiltered(texture, uv, lambda, true, MipSelect::None);
    case FilterMode::NearestMipmapNearest:
      return sampleFiltered(texture, uv, lambda, false, MipSelect::Nearest);
    case FilterMode::LinearMipmapNearest:
      return sampleFiltered(texture, uv, lambda, true, MipSelect::Nearest);
    case FilterMode::NearestMipmapLinear:
      return sampleFiltered(texture, uv, lambda, false, MipSelect::Linear);
    case FilterMode::LinearMipmapLinear:
      return sampleFiltered(texture, uv, lambda, true, MipSelect::Linear);
  }
  return sampleFiltered(texture, uv, lambda, true, MipSelect::Linear);
}

float lodFromGradients(const Texture& texture, vec2 dx, vec2 dy) {
  const vec2 size(float(texture.image.width), float(texture.image.height));
  const float rho = std::max(glm::length(dx * size), glm::length(dy * size));
  return rho > 0.f ? std::log2(rho) : -std::numeric_limits<float>::infinity();
}

vec4 sampleAnisotropic(const Texture& texture, vec2 uv, vec2 dx, vec2 dy, int maxAnisotropy) {
  const vec2 size(float(texture.image.width), float(texture.image.height));
  const float px = glm::length(dx * size), py = glm::length(dy * size);
  const float pmax = std::max(px, py), pmin = std::min(px, py);
  if (!(pmax > 0.f) || !std::isfinite(pmax))
    return sampleFiltered(texture, uv, 0.f, true, MipSelect::Linear);
  // Clamped as a float first: pmax / pmin can exceed any int.
  const float most = float(std::max(1, maxAnisotropy));
  const int n = int(std::clamp(pmin > 0.f ? std::ceil(pmax / pmin) : most, 1.f, most));
  const float lambda = std::log2(pmax / float(n));
  const vec2 axis = px >= py ? dx : dy;
  vec4 sum(0.f);
  for (int i = 0; i < n; ++i) {
    const float offset = (float(i) + 0.5f) / float(n) - 0.5f;  // stratified along the axis
    sum += sampleFiltered(texture, uv + offset * axis, lambda, true, MipSelect::Linear);
  }
  return sum / float(n);
}

vec3 checkerColor(const Checker& checker, vec2 uv) {
  const double a = std::floor(double(uv.x) * checker.scale);
  const double b = std::floor(double(uv.y) * checker.scale);
  if (!std::isfinite(a) || !std::isfinite(b)) return checker.colorA;
  // The parity of the sum s = |a + b|, an integer-valued double: s is even exactly when s / 2
  // (exact: a power-of-two scaling) is an integer, as fmod(s, 2) == 0 says, for every s (past
  // 2^53 every double is even), without fmod's libm call (1% of the Whitted reference, perf).
  const double half = 0.5 * std::fabs(a + b);
  return std::floor(half) == half ? checker.colorA : checker.colorB;
}

}  // namespace diptych
