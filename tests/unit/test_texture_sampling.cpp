// sampleNearest and sampleBilinear read texels without wrapTexel where no index leaves the image
// (engine/shading/texture_sampling.cpp, wrapPair). These tests hold them, bit for bit, to the
// general path: wrapTexel on every index and Image::at per channel, the same arithmetic.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "engine/shading/texture_sampling.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

// reduceCoordinate's rule (texture_sampling.cpp): whole periods of the wrap mode removed.
float reduced(float t, WrapMode mode) {
  if (!std::isfinite(t)) return 0.f;
  switch (mode) {
    case WrapMode::Repeat:
      return t - std::floor(t);
    case WrapMode::MirroredRepeat:
      return t - 2.f * std::floor(0.5f * t);
    case WrapMode::ClampToEdge:
      return t < -1.f ? -1.f : (t > 2.f ? 2.f : t);
  }
  return t;
}

vec4 generalTexel(const Image& image, int x, int y) {
  vec4 c(0.f, 0.f, 0.f, 1.f);
  for (int k = 0; k < std::min(image.channels, 4); ++k) c[k] = image.at(x, y, k);
  return image.channels == 1 ? vec4(c.x, c.x, c.x, 1.f) : c;
}

vec4 generalNearest(const Image& image, vec2 uv, WrapMode s, WrapMode t) {
  const float u = reduced(uv.x, s), v = reduced(uv.y, t);
  return generalTexel(image, wrapTexel(int(std::floor(u * float(image.width))), image.width, s),
                      wrapTexel(int(std::floor(v * float(image.height))), image.height, t));
}

vec4 generalBilinear(const Image& image, vec2 uv, WrapMode s, WrapMode t) {
  const float u = reduced(uv.x, s), v = reduced(uv.y, t);
  const float x = u * float(image.width) - 0.5f, y = v * float(image.height) - 0.5f;
  const float x0f = std::floor(x), y0f = std::floor(y);
  const float fx = x - x0f, fy = y - y0f;
  const int x0 = int(x0f), y0 = int(y0f), w = image.width, h = image.height;
  const int xa = wrapTexel(x0, w, s), xb = wrapTexel(x0 + 1, w, s);
  const int ya = wrapTexel(y0, h, t), yb = wrapTexel(y0 + 1, h, t);
  const vec4 top = glm::mix(generalTexel(image, xa, ya), generalTexel(image, xb, ya), fx);
  const vec4 bottom = glm::mix(generalTexel(image, xa, yb), generalTexel(image, xb, yb), fx);
  return glm::mix(top, bottom, fy);
}

Image numbered(int w, int h, int channels) {
  Image image(w, h, channels);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = float(i % 17) / 16.f + float(i) * 1e-3f;  // every value distinct
  return image;
}

// Coordinates across the image, at and around its edges (texel centres, the borders, one ulp
// either side of 0 and 1), beyond them, and the non-finite ones.
std::vector<float> coordinates(int size) {
  std::vector<float> c = {0.f,
                          -0.f,
                          1.f,
                          std::nextafter(0.f, -1.f),
                          std::nextafter(0.f, 1.f),
                          std::nextafter(1.f, 0.f),
                          std::nextafter(1.f, 2.f),
                          -1e-9f,
                          -0.37f,
                          1.61f,
                          -2.5f,
                          3.25f,
                          1e20f,
                          -1e20f,
                          INFINITY,
                          NAN};
  for (int i = -2 * size; i <= 2 * size; ++i) {
    c.push_back(float(i) / float(size));           // texel borders
    c.push_back((float(i) + 0.5f) / float(size));  // texel centres
    c.push_back((float(i) + 0.5f) / float(size) + 0.1f / float(size));
  }
  return c;
}

void expectSameBits(const vec4& a, const vec4& b, vec2 uv) {
  for (int k = 0; k < 4; ++k)
    ASSERT_EQ(std::bit_cast<std::uint32_t>(a[k]), std::bit_cast<std::uint32_t>(b[k]))
        << "channel " << k << " at uv (" << uv.x << ", " << uv.y << "): " << a[k] << " vs " << b[k];
}

TEST(TextureSampling, LookupsEqualTheGeneralPathAtEveryEdgeForEveryWrapMode) {
  const WrapMode modes[] = {WrapMode::Repeat, WrapMode::ClampToEdge, WrapMode::MirroredRepeat};
  const int sizes[][2] = {{1, 1}, {2, 3}, {5, 1}, {7, 4}};
  for (const auto& size : sizes)
    for (int channels = 1; channels <= 4; ++channels) {
      const Image image = numbered(size[0], size[1], channels);
      const std::vector<float> us = coordinates(size[0]), vs = coordinates(size[1]);
      for (WrapMode s : modes)
        for (WrapMode t : modes) {
          SCOPED_TRACE(::testing::Message() << size[0] << "x" << size[1] << "x" << channels
                                            << " wrap " << int(s) << "," << int(t));
          for (float u : us)
            for (float v : vs) {
              expectSameBits(sampleBilinear(image, {u, v}, s, t),
                             generalBilinear(image, {u, v}, s, t), {u, v});
              expectSameBits(sampleNearest(image, {u, v}, s, t),
                             generalNearest(image, {u, v}, s, t), {u, v});
            }
        }
    }
}

TEST(TextureSampling, GreyAndPartialChannelTexelsFillTheRestAsBefore) {
  // One texel each: grey repeats its value with alpha 1; two and three channels keep theirs and
  // fill 0 and alpha 1.
  Image grey(1, 1, 1, 0.25f), two(1, 1, 2, 0.5f), three(1, 1, 3, 0.75f);
  const WrapMode r = WrapMode::Repeat;
  EXPECT_EQ(sampleBilinear(grey, {0.3f, 0.6f}, r, r), vec4(0.25f, 0.25f, 0.25f, 1.f));
  EXPECT_EQ(sampleNearest(two, {0.3f, 0.6f}, r, r), vec4(0.5f, 0.5f, 0.f, 1.f));
  EXPECT_EQ(sampleBilinear(three, {0.3f, 0.6f}, r, r), vec4(0.75f, 0.75f, 0.75f, 1.f));
}

// The checker's parity test (floor(s / 2) == s / 2) against fmod(s, 2) == 0, the definition it
// replaced: every cell from -40 to 40 at several scales, cell boundaries, and coordinates whose
// cell indices pass 2^24 (float) and 2^53 (double), where every index is even.
TEST(TextureSampling, CheckerParityEqualsFmod) {
  const vec3 a(1.f, 0.f, 0.f), b(0.f, 1.f, 0.f);
  auto byFmod = [&](const Checker& c, vec2 uv) {
    const double x = std::floor(double(uv.x) * c.scale), y = std::floor(double(uv.y) * c.scale);
    if (!std::isfinite(x) || !std::isfinite(y)) return c.colorA;
    return std::fmod(std::fabs(x + y), 2.0) == 0.0 ? c.colorA : c.colorB;
  };
  int cellsB = 0;
  for (float scale : {1.f, 3.f, 8.f, 1e10f}) {
    const Checker c{a, b, scale};
    for (float u = -40.f; u <= 40.f; u += 0.37f)
      for (float v : {-40.f, -1.5f, -0.f, 0.f, 0.25f, 1.f, 7.75f, 39.5f}) {
        ASSERT_EQ(checkerColor(c, vec2(u, v)), byFmod(c, vec2(u, v))) << u << " " << v;
        cellsB += checkerColor(c, vec2(u, v)) == b ? 1 : 0;
      }
    for (float big : {16777216.f, 16777218.f, 1e16f, 9.007199e15f, 3e38f, -3e38f})
      for (float v : {0.f, 1.f, 2.5f})
        ASSERT_EQ(checkerColor(c, vec2(big, v)), byFmod(c, vec2(big, v))) << big << " " << v;
  }
  EXPECT_GT(cellsB, 100);  // both colours occur
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
