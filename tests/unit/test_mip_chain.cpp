// The lecture's mip chain (engine/scene/mip_chain.h) and the CPU sampler's level selection
// (engine/shading/texture_sampling.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "engine/scene/mip_chain.h"
#include "engine/shading/texture_sampling.h"
#include "tests/support/random_image.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

using ::diptych::testing::randomImage;

double mean(const Image& image, int c) {
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) sum += image.at(x, y, c);
  return sum / (double(image.width) * image.height);
}

// Power of two: every level is M_{i+1}[j,k] = 1/4 (M_i[2j,2k] + M_i[2j+1,2k] + M_i[2j,2k+1] +
// M_i[2j+1,2k+1]) of the one before, down to 1x1.
TEST(MipChain, PowerOfTwoLevelsAreTheLecturesBoxAverage) {
  const Image image = randomImage(32, 8, 4, 1);
  const std::vector<Image> chain = buildMipChain(image);
  ASSERT_EQ(chain.size(), 5u);  // 16x4, 8x2, 4x1, 2x1, 1x1
  const Image* previous = &image;
  for (const Image& level : chain) {
    EXPECT_EQ(level.width, std::max(1, previous->width / 2));
    EXPECT_EQ(level.height, std::max(1, previous->height / 2));
    for (int k = 0; k < level.height; ++k) {
      for (int j = 0; j < level.width; ++j) {
        for (int c = 0; c < 4; ++c) {
          // A side of 1 no longer halves: its two "rows" are the same row.
          const int j1 = previous->width > 1 ? 2 * j + 1 : 2 * j;
          const int k1 = previous->height > 1 ? 2 * k + 1 : 2 * k;
          const float box = 0.25f * (previous->at(2 * j, 2 * k, c) + previous->at(j1, 2 * k, c) +
                                     previous->at(2 * j, k1, c) + previous->at(j1, k1, c));
          EXPECT_NEAR(level.at(j, k, c), box, 1e-6f)
              << "level " << level.width << "x" << level.height << " texel " << j << "," << k;
        }
      }
    }
    previous = &level;
  }
  EXPECT_EQ(chain.back().width, 1);
  EXPECT_EQ(chain.back().height, 1);
  EXPECT_NEAR(chain.back().at(0, 0, 2), mean(image, 2), 1e-6);  // the top level is the mean
}

// Odd sides: w_{i+1} = floor(w_i / 2) (GL's sizes) and each texel the area-weighted mean of the
// interval it covers, so no texel is dropped and every level keeps the image's mean.
TEST(MipChain, OddSizesUseAreaWeightsAndKeepTheMean) {
  Image row(5, 1, 1);
  for (int x = 0; x < 5; ++x) row.at(x, 0, 0) = float(x + 1);  // 1 2 3 4 5
  const Image half = downsampleBox(row);
  ASSERT_EQ(half.width, 2);
  ASSERT_EQ(half.height, 1);
  // Texel 0 covers [0, 2.5): (1 + 2 + 0.5 * 3) / 2.5; texel 1 covers [2.5, 5).
  EXPECT_NEAR(half.at(0, 0, 0), (1.f + 2.f + 0.5f * 3.f) / 2.5f, 1e-6f);
  EXPECT_NEAR(half.at(1, 0, 0), (0.5f * 3.f + 4.f + 5.f) / 2.5f, 1e-6f);

  const Image image = randomImage(13, 7, 3, 2);
  const std::vector<Image> chain = buildMipChain(image);
  ASSERT_EQ(chain.size(), 3u);  // 6x3, 3x1, 1x1: floor(log2(13)) + 1 = 4 levels with level 0
  EXPECT_EQ(chain[0].width, 6);
  EXPECT_EQ(chain[0].height, 3);
  EXPECT_EQ(chain[1].width, 3);
  EXPECT_EQ(chain[1].height, 1);
  for (const Image& level : chain)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean(level, c), mean(image, c), 1e-5);
}

// Values of mixed signs and magnitudes, half of them from {1e20, -1e20, 1, 3e-5}, so that a
// different order of a texel's four additions would often give another float (1e20 + 1 - 1e20
// is 0 in double, 1e20 - 1e20 + 1 is 1).
Image wideRangeImage(int w, int h, int channels, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(-1.f, 1.f);
  std::uniform_int_distribution<int> exponent(-30, 30), pick(0, 7);
  const float cancelling[4] = {1e20f, -1e20f, 1.f, 3e-5f};
  Image image(w, h, channels);
  for (float& v : image.pixels) {
    const int p = pick(rng);
    v = p < 4 ? cancelling[p] : std::ldexp(unit(rng), exponent(rng));
  }
  return image;
}

bool sameBits(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

// Even sides take downsampleBox's 2:1 fast path: the same floats as the general area-weighted
// path, and as the general loop's sum written out here (0 + 0.25 a + 0.25 b + 0.25 c + 0.25 d in
// double, row by row), bit for bit; whole chains of power-of-two images likewise.
TEST(MipChain, EvenSidesFastPathEqualsTheGeneralPathBitForBit) {
  const int sizes[][3] = {{2, 2, 1}, {64, 32, 4}, {6, 10, 3}, {130, 66, 4}, {8, 2, 2}};
  unsigned seed = 10;
  for (const auto& size : sizes) {
    const Image image = wideRangeImage(size[0], size[1], size[2], seed++);
    const Image fast = downsampleBox(image);
    EXPECT_TRUE(sameBits(fast, downsampleBoxAreaWeights(image))) << size[0] << "x" << size[1];
    Image written(size[0] / 2, size[1] / 2, size[2]);
    for (int y = 0; y < written.height; ++y)
      for (int x = 0; x < written.width; ++x)
        for (int c = 0; c < size[2]; ++c) {
          double sum = 0.0;
          for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) sum += 0.25 * image.at(2 * x + dx, 2 * y + dy, c);
          written.at(x, y, c) = float(sum);
        }
    EXPECT_TRUE(sameBits(fast, written)) << size[0] << "x" << size[1];
  }
  const Image square = wideRangeImage(256, 64, 4, 20);
  const std::vector<Image> chain = buildMipChain(square);
  ASSERT_EQ(chain.size(), 8u);
  const Image* previous = &square;
  for (const Image& level : chain) {
    EXPECT_TRUE(sameBits(level, downsampleBoxAreaWeights(*previous))) << level.width;
    previous = &level;
  }
}

TEST(MipChain, EmptyAndSingleTexelImagesHaveNoLevels) {
  EXPECT_TRUE(buildMipChain(Image()).empty());
  EXPECT_TRUE(buildMipChain(Image(1, 1, 4, 0.5f)).empty());
  EXPECT_EQ(buildMipChain(Image(1, 8, 4)).size(), 3u);  // 1x4, 1x2, 1x1
}

Texture chainTexture(int w, int h) {
  Texture t;
  t.image = randomImage(w, h, 4, 3);
  t.mips = buildMipChain(t.image);
  return t;
}

// GL 4.5, 8.14.3: LINEAR_MIPMAP_LINEAR blends levels floor(lambda) and floor(lambda) + 1 by
// frac(lambda); NEAREST mips take d = ceil(lambda + 1/2) - 1; lambda is clamped to the chain.
TEST(MipChain, SamplerSelectsLevelsAsTheGlSpec) {
  const Texture t = chainTexture(16, 16);
  const vec2 uv(0.3f, 0.7f);
  const auto level = [&](int i) { return sampleBilinear(mipLevel(t, i), uv, t.wrapS, t.wrapT); };
  const vec4 at1 = sampleFiltered(t, uv, 1.f, true, MipSelect::Linear);
  const vec4 at1_25 = sampleFiltered(t, uv, 1.25f, true, MipSelect::Linear);
  const vec4 near1_4 = sampleFiltered(t, uv, 1.4f, true, MipSelect::Nearest);
  const vec4 near1_6 = sampleFiltered(t, uv, 1.6f, true, MipSelect::Nearest);
  const vec4 past = sampleFiltered(t, uv, 40.f, true, MipSelect::Linear);
  for (int c = 0; c < 4; ++c) {
    EXPECT_NEAR(at1[c], level(1)[c], 1e-6f);
    EXPECT_NEAR(at1_25[c], 0.75f * level(1)[c] + 0.25f * level(2)[c], 1e-6f);
    EXPECT_NEAR(near1_4[c], level(1)[c], 1e-6f);
    EXPECT_NEAR(near1_6[c], level(2)[c], 1e-6f);
    EXPECT_NEAR(past[c], level(4)[c], 1e-6f);  // 1x1: the mean
    // lambda <= 0 is magnification: level 0 whatever the mip mode.
    EXPECT_NEAR(sampleFiltered(t, uv, -3.f, true, MipSelect::Linear)[c], level(0)[c], 1e-6f);
  }
  EXPECT_EQ(mipLevelCount(t), 5);
}

TEST(MipChain, LodFromGradientsIsLog2OfTheTexelFootprint) {
  const Texture t = chainTexture(64, 32);
  EXPECT_NEAR(lodFromGradients(t, vec2(1.f / 64.f, 0.f), vec2(0.f, 1.f / 32.f)), 0.f, 1e-6f);
  EXPECT_NEAR(lodFromGradients(t, vec2(4.f / 64.f, 0.f), vec2(0.f, 1.f / 32.f)), 2.f, 1e-6f);
  // Anisotropic: a footprint 8 texels by 1 takes 8 probes at level 0, a blur of level 3 does not.
  const vec2 dx(8.f / 64.f, 0.f), dy(0.f, 1.f / 32.f), uv(0.41f, 0.37f);
  vec4 probes(0.f);
  for (int i = 0; i < 8; ++i)
    probes +=
        sampleFiltered(t, uv + ((float(i) + 0.5f) / 8.f - 0.5f) * dx, 0.f, true, MipSelect::Linear);
  const vec4 aniso = sampleAnisotropic(t, uv, dx, dy, 16);
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(aniso[c], probes[c] / 8.f, 1e-6f);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
