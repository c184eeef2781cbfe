#pragma once
// Image error metrics, each documented with its formula and source in docs/metrics.md.
// Images are linear RGB(A) floats (engine/core/image.h); alpha is ignored. Sizes must match
// (InputError otherwise, naming both images).
#include <map>
#include <string>
#include <vector>

#include "engine/core/image.h"

namespace diptych {

struct MetricOptions {
  // PSNR peak: the reference's maximum value by default (stated in the result as "psnr_peak");
  // set > 0 to force one (1.0 for LDR images).
  double psnrPeak = 0;
  double relMseEpsilon = 1e-2;  // relative MSE (x - r)^2 / (r^2 + eps)
  double ssimDataRange = 0;     // 0: max(reference) - min(reference), stated as "ssim_data_range"
  double flipPixelsPerDegree = 67.0;  // FLIP viewing condition (0.7 m, 0.7 m wide 4K monitor)
};

// Every scalar metric: mse, rmse, relmse, psnr (+ psnr_peak), ssim (+ ssim_data_range),
// flip_mean, flip_p50, flip_p95, flip_p99 (LDR FLIP on the sRGB tone-mapped images when both
// are within [0,1], HDR-FLIP otherwise; "flip_variant" records which: 0 = LDR, 1 = HDR).
std::map<std::string, double> computeMetrics(const Image& test, const Image& reference,
                                             const MetricOptions& options = {});

// Per-pixel error maps (one channel, same size) for heat maps.
Image squaredErrorMap(const Image& test, const Image& reference);
Image flipErrorMap(const Image& test, const Image& reference, const MetricOptions& options = {});

// A perceptual colour map (e.g. viridis or magma) of a one-channel map scaled to [0, maxValue].
Image heatMap(const Image& values, float maxValue);

}  // namespace diptych
