#pragma once
// `diptych sweep` (docs/sweep.md): the cartesian product of parameter values of one slot
// producer, each point measured against the exact producer of the same slot on the same
// G-buffer, one exact reference per distinct scene state. results.json / results.csv are
// rewritten after every point, so an interrupted sweep resumes from what it wrote.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/scene/scene.h"
#include "samples/diptych/sweep/spec.h"

namespace diptych::cli {

struct SweepOptions {
  std::string scene;
  std::string producer;  // SLOT=TYPE[:key=value,...], the fixed part of every point
  std::vector<SweepAxis> axes;
  int width = 320, height = 240, frames = 1, warmup = 0;
  int light = 0;             // the light whose visibility is classified and --vary-light moves
  int band = 2, reach = 16;  // classifyShadows (engine/metrics/signal_metrics.h)
  double contact = -1;       // contact distance, world (< 0: 1e-3 x the scene's diagonal)
  std::string shading;       // --shading lecture|gltf (empty: each material its own)
  std::string receiver;      // restrict the measurement to this object's pixels (empty: all)
  std::filesystem::path out = "sweep";
  const char* label = "sweep";  // progress prefix
};

// Validates everything (axes, keys through the producer's own parameter checks, the receiver,
// a resumable results.json) before rendering; then renders the missing points. Returns the
// results.json document: {"spec", "method", "points": [...]}.
nlohmann::json runSweep(const SweepOptions& options);

// The scene with light `light` turned to the point's "elevation" / "azimuth" (degrees; either
// may be absent and keeps the light's own): elevation above the xz plane, azimuth from +x
// toward +z; the light travels toward the scene. Without either key: the scene unchanged.
Scene sceneAt(const Scene& base, const nlohmann::json& point, int light);

}  // namespace diptych::cli
