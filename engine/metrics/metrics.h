#pragma once
// Image error metrics, each documented with its formula and source in docs/metrics.md.
// Images are linear RGB(A) floats (engine/core/image.h); alpha is ignored. Sizes must match
// (InputError otherwise, naming both images).
#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "engine/core/image.h"

namespace diptych {

// FLIP pixels per degree accepted (docs/robustness.md): 1 (a thumbnail seen from far away) to
// 1000 (beyond any display); the filter radii grow as 0.135 * ppd pixels, so 1e9 would mean
// kernels of 1e8 taps and minutes per image. Outside the range computeMetrics throws InputError.
constexpr double kMinFlipPpd = 1.0, kMaxFlipPpd = 1000.0;

struct MetricOptions {
  // PSNR peak: the reference's maximum value by default (stated in the result as "psnr_peak");
  // set > 0 to force one (1.0 for LDR images).
  double psnrPeak = 0;
  double relMseEpsilon = 1e-2;  // relative MSE (x - r)^2 / (r^2 + eps)
  double ssimDataRange = 0;     // 0: max(reference) - min(reference), stated as "ssim_data_range"
  double flipPixelsPerDegree = 67.0;  // FLIP viewing condition (0.7 m, 0.7 m wide 4K monitor)

  // Additions beyond the original contract.
  // Names used in errors (size mismatch, non-finite values): file names in `diptych diff`.
  std::string testName = "test image", referenceName = "reference image";
  // Metric groups to compute: any of "mse", "rmse", "relmse", "psnr", "ssim", "flip";
  // empty means all. Unknown names throw InputError.
  std::vector<std::string> metrics;
};

// Every scalar metric: mse, rmse, relmse, psnr (+ psnr_peak), ssim (+ ssim_data_range),
// flip_mean, flip_p50, flip_p95, flip_p99 (LDR FLIP on the sRGB tone-mapped images when both
// are within [0,1], HDR-FLIP otherwise; "flip_variant" records which: 0 = LDR, 1 = HDR).
// HDR-FLIP also states "flip_exposure_start", "flip_exposure_stop", "flip_exposure_count";
// every FLIP result states "flip_pixels_per_degree". PSNR of identical images is +infinity.
std::map<std::string, double> computeMetrics(const Image& test, const Image& reference,
                                             const MetricOptions& options = {});

// The metric group names computeMetrics accepts in MetricOptions::metrics.
const std::vector<std::string>& metricGroupNames();

// Per-pixel error maps (one channel, same size) for heat maps.
Image squaredErrorMap(const Image& test, const Image& reference);
Image flipErrorMap(const Image& test, const Image& reference, const MetricOptions& options = {});

// A perceptual colour map (e.g. viridis or magma) of a one-channel map scaled to [0, maxValue].
// Returns linear RGB, so that writeImage's sRGB encoding reproduces the published colours.
Image heatMap(const Image& values, float maxValue);
// The colour map itself: sRGB-encoded viridis at t in [0, 1] (clamped).
std::array<float, 3> viridisSrgb(float t);

// --- Individual metrics (all over the colour channels: RGB, or grey) ---
double meanSquaredError(const Image& test, const Image& reference);
double relativeMeanSquaredError(const Image& test, const Image& reference, double epsilon);
// 10 log10(peak^2 / MSE); +infinity when MSE is 0.
double psnr(const Image& test, const Image& reference, double peak);
// Mean SSIM (Gaussian 11x11, sigma 1.5, K1 0.01, K2 0.03), per channel and averaged, like
// scikit-image's structural_similarity(channel_axis=-1, gaussian_weights=True,
// use_sample_covariance=False).
double ssim(const Image& test, const Image& reference, double dataRange);

struct FlipResult {
  Image map;  // one channel, per-pixel FLIP error in [0, 1]
  bool hdr = false;
  double exposureStart = 0, exposureStop = 0;
  int exposureCount = 0;
};
// LDR-FLIP on images whose values are display-referred linear RGB in [0,1].
FlipResult ldrFlip(const Image& test, const Image& reference, double pixelsPerDegree);
// HDR-FLIP: LDR-FLIP over a range of exposures of the ACES-like tone mapper, maximum per pixel.
// At most kMaxHdrFlipExposures exposures: the paper's count is log2 of the reference's
// brightest-to-median range, up to 277 for float data (each one a whole LDR-FLIP); a range above
// 2^64 only comes from broken or hostile input and gets wider steps instead (docs/metrics.md).
constexpr int kMaxHdrFlipExposures = 64;
FlipResult hdrFlip(const Image& test, const Image& reference, double pixelsPerDegree);

// Reads an image for comparison: float files (EXR, HDR) as stored; integer files (PNG, JPEG,
// TIFF 8/16-bit) are display-encoded and decoded with the sRGB transfer function to linear
// (alpha untouched). Throws InputError naming the file.
Image readLinearImage(const std::filesystem::path& path);

}  // namespace diptych
