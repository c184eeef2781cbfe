#pragma once
// The per-pixel sphere-tracing signal `sdf_steps` (issue 10: "count steps per ray ... as a
// signal the report can show as a heat map"), written by traced producers when the scene has
// SDF objects. RGBA32F per pixel, over every ray the pixel traced (all samples, the whole ray
// tree, shadow rays included) that reached an SDF object's box:
//   R: sphere-tracing steps (distance evaluations) summed, G: such rays,
//   B: the most steps of one of them, A: of them, misses by the iteration cap.
// So the frame's sums of R, G and A and its max of B are RtScene::sdfStepStats() for that frame.
#include <algorithm>

#include "engine/core/image.h"
#include "engine/graph/pass.h"
#include "engine/scene/sdf.h"

namespace diptych {

inline bool sceneHasSdf(const Scene& scene) {
  return std::any_of(scene.meshes.begin(), scene.meshes.end(),
                     [](const Mesh& m) { return m.sdf != nullptr; });
}

// Declares the output where the scene has SDF objects; kNoResource otherwise.
inline ResourceId writeSdfSteps(PassBuilder& b) {
  if (!sceneHasSdf(b.scene())) return kNoResource;
  return b.write("sdf_steps", {Format::RGBA32F, b.frame().width, b.frame().height}, vec4(0.f));
}

// Clears this thread's tally before a pixel's rays (engine/scene/sdf.h: SdfRayTally).
inline void beginSdfPixel() {
  threadSdfTally() = {};
}

// Stores this thread's tally as pixel (x, y) of `out` (null: no output, nothing to do).
inline void storeSdfPixel(CpuImage* out, int x, int y) {
  if (!out) return;
  const SdfRayTally& t = threadSdfTally();
  out->setF(x, y, 0, float(t.steps));
  out->setF(x, y, 1, float(t.rays));
  out->setF(x, y, 2, float(t.maxSteps));
  out->setF(x, y, 3, float(t.capped));
}

// The frame's figures from an sdf_steps image: the per-ray mean is sum R / sum G.
struct SdfStepSummary {
  double rays = 0, steps = 0, capped = 0, maxSteps = 0, maxPixelSteps = 0;
  double meanSteps() const { return rays > 0 ? steps / rays : 0.0; }
};
inline SdfStepSummary summariseSdfSteps(const Image& image) {
  SdfStepSummary s;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      s.steps += image.at(x, y, 0);
      s.rays += image.at(x, y, 1);
      s.maxSteps = std::max(s.maxSteps, double(image.at(x, y, 2)));
      s.capped += image.at(x, y, 3);
      s.maxPixelSteps = std::max(s.maxPixelSteps, double(image.at(x, y, 0)));
    }
  return s;
}

}  // namespace diptych
