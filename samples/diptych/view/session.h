#pragma once
// The viewer's model, without any window code: the scene, the current recipe (a base recipe plus
// per-slot overrides), the reference, the camera, and the compiled graphs that render them. It
// renders through the same compileGraph/GraphExecutor as `diptych render` and measures with the
// same engine/metrics as `diptych compare`, so a frame here is a frame there.
#include <map>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/image.h"
#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"
#include "passes/slots.h"

namespace diptych::view {

// A compiled graph and the executor that runs it (the executor refers to the graph, so it is
// declared after it and destroyed first).
struct LiveGraph {
  CompiledGraph graph;
  std::unique_ptr<GraphExecutor> executor;
  int frames = 0;  // the first carries one-time work (BVH, shaders, pool allocation)
};

// Error figures of the last full-resolution idle frame against the reference (docs/metrics.md).
struct Figures {
  bool valid = false;
  double rmse = 0, flipMean = 0;
  bool visibility = false;  // the visibility slot differs from the reference's: classifyShadows
  double acneRate = 0, peterPanningRate = 0, lightLeakRate = 0;
  int referenceSamples = 0;  // the progressive path reference's count when measured (0: n/a)
  nlohmann::json toJson() const;
};

class Session {
 public:
  // `reference`: "hybrid" (every slot exact), "whitted", "distributed:SPP", "path[:SPP]"
  // (accumulates one sample per idle frame) or a recipe file. Throws InputError.
  Session(Scene& scene, std::string scenePath, gl::GlContext& context, Recipe base,
          const std::string& reference);

  // --- state ---
  const Scene& scene() const { return scene_; }
  const std::string& scenePath() const { return scenePath_; }
  Camera& camera() { return camera_; }
  const Camera& sceneCamera() const { return sceneCamera_; }
  void cameraChanged();   // refits near/far and marks the frame stale
  Recipe recipe() const;  // base + overrides
  // Current producer of each slot: "TYPE" and its parameter values, from the recipe.
  struct SlotState {
    std::string type;
    nlohmann::json params = nlohmann::json::object();
  };
  std::optional<SlotState> slotState(const std::string& slot) const;
  // Sets a slot's producer and parameters (SlotOverride as --slot parses it). The recipe is
  // recompiled at once; on an InputError the previous state is kept and the error returned.
  std::optional<std::string> setSlot(const SlotOverride& override);
  std::optional<std::string> setParam(const std::string& slot, const std::string& key,
                                      const nlohmann::json& value);
  const std::string& referenceText() const { return referenceText_; }

  // --- rendering ---
  // Renders the current recipe at width x height (the reference too when `withReference`) and,
  // when `measure`, the figures. Returns false when nothing changed since the last call.
  bool render(int width, int height, bool withReference, bool measure);
  // Runs the current graph `frames` more times (same camera) so that the timing panel holds a
  // median of warm frames: a resting viewer renders nothing, so its panel has only what moved.
  void timeFrames(int frames);
  const Image& current() const { return current_; }
  const Image& reference() const { return reference_; }
  const Image& errorMap() const { return errorMap_; }  // FLIP per pixel of the last measure
  const Figures& figures() const { return figures_; }
  const LiveGraph* live() const { return live_.get(); }
  double lastFrameMs() const { return lastFrameMs_; }
  // The last frame was not its graph's first, so lastFrameMs() holds no one-time work.
  bool lastFrameWarm() const { return live_ && live_->frames > 1; }
  int referenceSamples() const { return referenceSamples_; }
  nlohmann::json stateJson() const;

 private:
  void compile(int width, int height);
  void renderReference(int width, int height);
  void measure();

  Scene& scene_;
  std::string scenePath_;
  RenderWorld world_;
  Camera sceneCamera_, camera_;
  Recipe base_;
  std::map<std::string, SlotOverride> overrides_;
  std::string referenceText_;
  Recipe referenceRecipe_;
  bool progressiveReference_ = false;  // path: one sample per frame, averaged here

  std::unique_ptr<LiveGraph> live_, liveReference_;
  bool stale_ = true, referenceStale_ = true, measured_ = false;
  int referenceSamples_ = 0;
  Image current_, reference_, referenceSum_, errorMap_;
  Figures figures_;
  double lastFrameMs_ = 0;
};

}  // namespace diptych::view
