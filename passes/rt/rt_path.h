#pragma once
#include "engine/graph/pass.h"

namespace diptych {

// The path-traced global-illumination reference (engine/rt/path_tracer.h; Kajiya 1986).
// Progressive: whole passes of one sample per pixel (uniformly jittered in the pixel, through
// the thin lens when Camera::aperture > 0) until `spp` passes are done or, with
// `time_budget_ms` > 0, the time is exceeded at the end of a pass (at least one pass runs).
// Without a budget a pixel's spp samples run one after another instead (the same samples, in
// the same order for the running mean; no image of accumulators goes through memory spp
// times). Either way a row's paths go in chunks of PathTracer::kMaxPaths: their camera rays as
// one coherent Embree stream (CameraRays::intersectRays), then the chunk vertex by vertex
// (PathTracer's wavefront: each level's hits and shadow rays as streams). 0.81x the CPU time
// of path-by-path tracing on whitted 640x480, 0.86x on cornell 320x240; the stream kernels
// may round a camera hit's last bits differently from the single-ray ones
// (docs/reference-renderers.md).
// Each pixel keeps a running mean and variance (Welford, "Note on a Method for Calculating
// Corrected Sums of Squares and Products", Technometrics 1962) in double precision.
// Every sample's random sequence depends only on (pixel, pass, seed): reproducible.
// Params: schema() (`diptych passes` lists them).
// Outputs: color RGBA32F: the mean (alpha 1);
//          variance RGBA32F: rgb = variance of the mean per channel, s^2 / n with the unbiased
//          sample variance s^2 (0 when n < 2); alpha = n, the samples taken per pixel.
// Counters: rays (intersection + shadow), samples (pixel samples taken), passes,
//           invalid_samples (non-finite samples replaced by 0; expected 0).
class RtPathPass : public Pass {
 public:
  static ParamSchema schema();
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  int spp_ = 16, maxDepth_ = 16, rrDepth_ = 3, seed_ = 0;
  bool rayCones_ = false;
  double timeBudgetMs_ = 0.0;
  bool russianRoulette_ = true;
  ResourceId color_ = kNoResource, variance_ = kNoResource;
};

}  // namespace diptych
