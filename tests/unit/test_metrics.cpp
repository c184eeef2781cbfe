// Image error metrics (engine/metrics): hand-computed values, properties of SSIM and FLIP on
// procedural images, error reporting, the heat map colours.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "engine/core/error.h"
#include "engine/metrics/metrics.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

Image pixels2x1(std::initializer_list<float> values, int channels = 3) {
  Image img(2, 1, channels);
  img.pixels.assign(values);
  return img;
}

// A structured test picture: gradients, a disc, a bar pattern and a checkered square, scaled by
// `peak` (1 for LDR, > 1 for HDR).
Image scene(int w, int h, float peak = 1.f) {
  Image img(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float u = float(x) / float(w - 1), v = float(y) / float(h - 1);
      float r = 0.2f + 0.6f * u, g = 0.1f + 0.7f * v, b = 0.5f - 0.3f * u * v;
      const float dx = u - 0.35f, dy = v - 0.4f;
      if (dx * dx + dy * dy < 0.04f) r = 0.9f, g = 0.85f, b = 0.2f;
      if (u > 0.6f && u < 0.9f && v > 0.55f && v < 0.9f && ((x / 4 + y / 4) % 2 == 0))
        r = g = b = 0.05f;
      if (v < 0.15f && (x / 3) % 2 == 0) r = g = b = 0.95f;
      img.at(x, y, 0) = r * peak;
      img.at(x, y, 1) = g * peak;
      img.at(x, y, 2) = b * peak;
    }
  // A small, very bright highlight so HDR images have a real range of exposures.
  if (peak > 1)
    for (int y = h / 5; y < h / 5 + 3; ++y)
      for (int x = w / 2; x < w / 2 + 3; ++x)
        for (int c = 0; c < 3; ++c) img.at(x, y, c) = 8 * peak;
  return img;
}

// Additive (LDR, clamped to [0,1]) or multiplicative (HDR) Gaussian noise, fixed seed.
Image withNoise(const Image& src, float sigma, bool hdr = false) {
  Image out = src;
  std::mt19937 rng(1234);
  std::normal_distribution<float> n(0.f, sigma);
  for (float& v : out.pixels)
    v = hdr ? std::max(0.f, v * (1.f + n(rng))) : std::clamp(v + n(rng), 0.f, 1.f);
  return out;
}

// Box blur of the given radius, clamp-to-edge, separable.
Image withBlur(const Image& src, int radius) {
  Image tmp = src, out = src;
  for (int pass = 0; pass < 2; ++pass) {
    const Image& in = pass == 0 ? src : tmp;
    Image& dst = pass == 0 ? tmp : out;
    for (int y = 0; y < src.height; ++y)
      for (int x = 0; x < src.width; ++x)
        for (int c = 0; c < src.channels; ++c) {
          float s = 0;
          for (int k = -radius; k <= radius; ++k) {
            const int xx = pass == 0 ? std::clamp(x + k, 0, src.width - 1) : x;
            const int yy = pass == 1 ? std::clamp(y + k, 0, src.height - 1) : y;
            s += in.at(xx, yy, c);
          }
          dst.at(x, y, c) = s / float(2 * radius + 1);
        }
  }
  return out;
}

TEST(Metrics, HandComputedPixelMetrics) {
  // Differences: pixel 0 red -0.5, pixel 1 green +0.5; six colour samples.
  const Image ref = pixels2x1({1.f, 0.5f, 0.f, 0.25f, 0.25f, 0.25f});
  const Image test = pixels2x1({0.5f, 0.5f, 0.f, 0.25f, 0.75f, 0.25f});
  const auto m = computeMetrics(test, ref, {.metrics = {"mse", "rmse", "relmse", "psnr"}});
  EXPECT_NEAR(m.at("mse"), 0.5 / 6, 1e-12);
  EXPECT_NEAR(m.at("rmse"), std::sqrt(0.5 / 6), 1e-12);
  // (0.25 / (1 + 0.01) + 0.25 / (0.0625 + 0.01)) / 6
  EXPECT_NEAR(m.at("relmse"), (0.25 / 1.01 + 0.25 / 0.0725) / 6, 1e-7);
  EXPECT_DOUBLE_EQ(m.at("psnr_peak"), 1.0);  // the reference's maximum
  EXPECT_NEAR(m.at("psnr"), 10 * std::log10(12.0), 1e-9);
  EXPECT_EQ(m.count("ssim"), 0u);
  // A forced peak of 2: 10 log10(4 / (1/12)).
  const auto forced = computeMetrics(test, ref, {.psnrPeak = 2, .metrics = {"psnr"}});
  EXPECT_NEAR(forced.at("psnr"), 10 * std::log10(48.0), 1e-9);
  EXPECT_DOUBLE_EQ(forced.at("psnr_peak"), 2.0);
}

TEST(Metrics, PsnrPeakIsTheHdrReferencesMaximumNotOne) {
  const Image ref = pixels2x1({4.f, 0.f, 0.f, 0.f, 0.f, 0.f});
  const Image test = pixels2x1({3.f, 0.f, 0.f, 0.f, 0.f, 0.f});
  const auto m = computeMetrics(test, ref, {.metrics = {"psnr"}});
  EXPECT_DOUBLE_EQ(m.at("psnr_peak"), 4.0);
  EXPECT_NEAR(m.at("psnr"), 10 * std::log10(16.0 / (1.0 / 6)), 1e-9);
}

TEST(Metrics, AlphaIsIgnoredAndGreyIsBroadcast) {
  const Image ref = pixels2x1({1.f, 0.5f, 0.f, 1.f, 0.25f, 0.25f, 0.25f, 0.f}, 4);
  const Image test = pixels2x1({0.5f, 0.5f, 0.f, 0.f, 0.25f, 0.75f, 0.25f, 1.f}, 4);
  EXPECT_NEAR(meanSquaredError(test, ref), 0.5 / 6, 1e-12);
  const Image grey = pixels2x1({0.5f, 0.25f}, 1);
  const Image rgb = pixels2x1({0.5f, 0.5f, 0.5f, 0.25f, 0.25f, 1.25f});
  EXPECT_NEAR(meanSquaredError(grey, rgb), 1.0 / 6, 1e-12);
}

TEST(Metrics, IdenticalImagesHaveNoError) {
  const Image a = scene(48, 32);
  const auto m = computeMetrics(a, a);
  EXPECT_EQ(m.at("mse"), 0);
  EXPECT_EQ(m.at("rmse"), 0);
  EXPECT_EQ(m.at("relmse"), 0);
  EXPECT_TRUE(std::isinf(m.at("psnr")));
  EXPECT_NEAR(m.at("ssim"), 1.0, 1e-12);
  EXPECT_EQ(m.at("flip_mean"), 0);
  EXPECT_EQ(m.at("flip_p99"), 0);
  EXPECT_EQ(m.at("flip_variant"), 0);
}

TEST(Metrics, SsimIsSymmetricAndDecreasesWithNoise) {
  const Image a = scene(64, 40);
  const Image b = withNoise(a, 0.05f);
  EXPECT_NEAR(ssim(a, b, 1.0), ssim(b, a, 1.0), 1e-12);
  double previous = ssim(a, a, 1.0);
  EXPECT_NEAR(previous, 1.0, 1e-12);
  for (float sigma : {0.01f, 0.03f, 0.1f, 0.3f}) {
    const double s = ssim(withNoise(a, sigma), a, 1.0);
    EXPECT_LT(s, previous) << "noise sigma " << sigma;
    previous = s;
  }
}

TEST(Metrics, FlipIsZeroOnIdenticalAndGrowsWithNoise) {
  const Image a = scene(64, 48);
  EXPECT_EQ(computeMetrics(a, a, {.metrics = {"flip"}}).at("flip_mean"), 0);
  double previous = 0;
  for (float sigma : {0.01f, 0.03f, 0.1f, 0.3f}) {
    const auto m = computeMetrics(withNoise(a, sigma), a, {.metrics = {"flip"}});
    EXPECT_EQ(m.at("flip_variant"), 0);
    EXPECT_GT(m.at("flip_mean"), previous) << "noise sigma " << sigma;
    EXPECT_LE(m.at("flip_p50"), m.at("flip_p95"));
    EXPECT_LE(m.at("flip_p95"), m.at("flip_p99"));
    EXPECT_LE(m.at("flip_p99"), 1.0);
    previous = m.at("flip_mean");
  }
}

TEST(Metrics, FlipGrowsWithBlur) {
  const Image a = scene(64, 48);
  double previous = 0;
  for (int radius : {1, 2, 4, 8}) {
    const double f = computeMetrics(withBlur(a, radius), a, {.metrics = {"flip"}}).at("flip_mean");
    EXPECT_GT(f, previous) << "blur radius " << radius;
    previous = f;
  }
}

TEST(Metrics, HdrFlipIsZeroOnIdenticalAndGrowsWithNoiseAndBlur) {
  const Image a = scene(64, 48, 6.f);
  const auto same = computeMetrics(a, a, {.metrics = {"flip"}});
  EXPECT_EQ(same.at("flip_variant"), 1);
  EXPECT_EQ(same.at("flip_mean"), 0);
  EXPECT_LT(same.at("flip_exposure_start"), same.at("flip_exposure_stop"));
  EXPECT_GE(same.at("flip_exposure_count"), 2);
  double previous = 0;
  for (float sigma : {0.02f, 0.05f, 0.15f, 0.4f}) {
    const double f =
        computeMetrics(withNoise(a, sigma, true), a, {.metrics = {"flip"}}).at("flip_mean");
    EXPECT_GT(f, previous) << "noise sigma " << sigma;
    previous = f;
  }
  previous = 0;
  for (int radius : {1, 2, 4, 8}) {
    const double f = computeMetrics(withBlur(a, radius), a, {.metrics = {"flip"}}).at("flip_mean");
    EXPECT_GT(f, previous) << "blur radius " << radius;
    previous = f;
  }
}

TEST(Metrics, FlipMapMatchesTheMean) {
  const Image a = scene(40, 30), b = withNoise(a, 0.1f);
  const Image map = flipErrorMap(b, a);
  ASSERT_EQ(map.channels, 1);
  double sum = 0;
  for (float v : map.pixels) sum += v;
  EXPECT_NEAR(sum / double(map.pixels.size()),
              computeMetrics(b, a, {.metrics = {"flip"}}).at("flip_mean"), 1e-6);
  const Image sq = squaredErrorMap(b, a);
  sum = 0;
  for (float v : sq.pixels) sum += v;
  EXPECT_NEAR(sum / double(sq.pixels.size()), meanSquaredError(b, a), 1e-6);
}

TEST(Metrics, SizeMismatchNamesBothImages) {
  MetricOptions o;
  o.testName = "render.exr";
  o.referenceName = "truth.exr";
  try {
    computeMetrics(Image(4, 3, 3), Image(3, 4, 3), o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("render.exr"), std::string::npos) << what;
    EXPECT_NE(what.find("truth.exr"), std::string::npos) << what;
    EXPECT_NE(what.find("4x3"), std::string::npos) << what;
    EXPECT_NE(what.find("3x4"), std::string::npos) << what;
  }
  EXPECT_THROW(meanSquaredError(Image(2, 2, 3), Image(2, 1, 3)), InputError);
}

TEST(Metrics, NonFiniteValuesAndUnknownMetricsAreErrors) {
  Image a(2, 2, 3, 0.5f), b = a;
  b.at(1, 0, 2) = std::nanf("");
  EXPECT_THROW(computeMetrics(a, b), InputError);
  EXPECT_THROW(computeMetrics(a, a, {.metrics = {"bogus"}}), InputError);
}

TEST(Metrics, ViridisMatchesMatplotlibsTable) {
  // matplotlib's _viridis_data at entries 0, 128 and 255.
  const auto near = [](std::array<float, 3> got, std::array<float, 3> want) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 0.015f) << "channel " << c;
  };
  near(viridisSrgb(0.f), {0.267004f, 0.004874f, 0.329415f});
  near(viridisSrgb(128.f / 255.f), {0.127568f, 0.566949f, 0.550556f});
  near(viridisSrgb(1.f), {0.993248f, 0.906157f, 0.143936f});
  // Lightness grows monotonically (a property of viridis that makes it readable in grey).
  float previous = -1;
  for (int i = 0; i <= 20; ++i) {
    const auto c = viridisSrgb(float(i) / 20);
    const float luma =
        0.2126f * srgbToLinear(c[0]) + 0.7152f * srgbToLinear(c[1]) + 0.0722f * srgbToLinear(c[2]);
    EXPECT_GT(luma, previous);
    previous = luma;
  }
  const Image heat = heatMap(Image(1, 1, 1, 0.5f), 1.f);
  EXPECT_NEAR(linearToSrgb(heat.at(0, 0, 1)), viridisSrgb(0.5f)[1], 1e-5);
}

TEST(Metrics, ReadLinearImageDecodesPngButNotExr) {
  const auto dir = ::diptych::testing::scratchDir("diptych_metrics_io");
  std::filesystem::create_directories(dir);
  const Image grey(2, 2, 3, 0.5f);
  writeImage(dir / "g.png", grey);  // sRGB encoded on write
  writeImage(dir / "g.exr", grey);
  EXPECT_NEAR(readLinearImage(dir / "g.png").at(0, 0, 0), 0.5f, 0.005f);
  EXPECT_EQ(readLinearImage(dir / "g.exr").at(1, 1, 2), 0.5f);
  EXPECT_THROW(readLinearImage(dir / "missing.png"), InputError);
}

TEST(Metrics, FlipOfFlatImagesIsTheCompressedHyabDistance) {
  // On constant images the unit-sum CSF filters change nothing and there are no features, so
  // FLIP is the compressed colour difference alone. Expected values computed by hand from the
  // published CIELAB coordinates of sRGB green (87.735, -86.183, 83.179) and blue (32.303,
  // 79.197, -107.864): cmax = HyAB(Hunt(green), Hunt(blue))^0.7 = 41.276.
  //   black vs white: HyAB = 100, 100^0.7 = 25.12 > 0.4 cmax -> 0.95 + ... = 0.96738.
  //   linear grey 0.5 vs 0.25: L* 76.069 vs 57.075, 18.994^0.7 / (0.4 cmax) * 0.95 = 0.45185.
  const auto flat = [](float v) { return Image(24, 16, 3, v); };
  EXPECT_NEAR(flipErrorMap(flat(0.f), flat(1.f)).at(5, 7, 0), 0.96738, 2e-4);
  EXPECT_NEAR(flipErrorMap(flat(0.5f), flat(0.25f)).at(11, 3, 0), 0.45185, 2e-4);
}

// A hostile HDR reference (brightest over median pixel 2^200) costs at most kMaxHdrFlipExposures
// LDR-FLIP runs, spread over the paper's whole exposure range (fuzz_image spent seconds per input).
TEST(Flip, ExposureCountIsBoundedOnAnExtremeRange) {
  Image reference(4, 4, 3), test(4, 4, 3);
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    reference.pixels[i] = (i / 3) % 4 == 0 ? 1e30f : 1e-30f;  // median tiny, maximum huge
    test.pixels[i] = reference.pixels[i] * 0.5f;
  }
  const FlipResult r = hdrFlip(test, reference, 67.0);
  EXPECT_EQ(r.exposureCount, kMaxHdrFlipExposures);
  EXPECT_GT(r.exposureStop - r.exposureStart, 150.0) << "the whole range is still covered";
  for (float v : r.map.pixels) EXPECT_TRUE(std::isfinite(v) && v >= 0.f && v <= 1.f);
}
}  // namespace DIPTYCH_UNITY_ID
