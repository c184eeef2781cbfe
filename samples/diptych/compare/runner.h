#pragma once
// Runs one recipe for a comparison: warm-up frames, measured frames, and copies of the
// requested outputs.
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"

namespace diptych::cli {

struct GraphRun {
  CompiledGraph graph;
  std::vector<NodeTiming> timings;
  std::map<std::string, CpuImage> outputs;
  double totalMs = 0;  // sum over nodes of each node's median CPU time, less measurement-only
                       // readbacks (GraphNode::forOutputOnly) of outputs other than the first
  // The first frame's CPU time (every node): it carries one-time work (shader compilation, pool
  // allocation, first-use caches) that the median of the measured frames leaves out.
  double firstFrameMs = 0;
  // The first frame against a steady one (firstFrameJson, engine/graph/export.h): the first-use
  // work nothing records (a GL driver compiling programs at their first draw), per node.
  nlohmann::json firstFrame;
  // One-time work the run did for the world (a static shadow map, ...): never in a median.
  std::map<std::string, double> oneTimeMs;
  std::string glSync;  // when the executor waited for the GL (GraphExecutor::glSyncReason)
  double rays = 0;     // rays counted by the passes in the last frame
  nlohmann::json passMs = nlohmann::json::object();  // node name -> median ms (runner.cpp: GL
                                                     // passes CPU + GL, transfers GL)
};

GraphRun runGraph(const Recipe& recipe, RenderWorld& world, const FrameSettings& frame,
                  const std::vector<std::string>& outputs, int warmup, int frames);
// The same for a graph already compiled for `world` with `outputs` (compare inspects it first).
GraphRun runCompiled(CompiledGraph graph, RenderWorld& world,
                     const std::vector<std::string>& outputs, int warmup, int frames);

// The accumulation buffer (Haeberli and Akeley, "The Accumulation Buffer", SIGGRAPH 1990): the
// recipe run on each world (a scene's snapshot at one instant of the shutter, sceneAtTime) and
// the first output averaged over them; the other outputs are dropped. The N frames make one
// frame of the technique: times (totalMs, passMs, firstFrameMs), rays and one-time costs are
// summed; graph, timings and first-frame details are the first instant's.
GraphRun runAccumulated(const Recipe& recipe, std::span<const std::unique_ptr<RenderWorld>> worlds,
                        const FrameSettings& frame, const std::vector<std::string>& outputs,
                        int warmup, int frames);

// The resource that feeds shade's input for `slot` ("visibility" -> "shadows.visibility"),
// or empty when the recipe has no producer for it.
std::string slotSignal(const Recipe& recipe, const std::string& slot);

// One line of progress on stderr: a bar on a terminal, a plain "LABEL: done/total what" line
// otherwise (logs, CI).
void progress(const char* label, int done, int total, const std::string& what);
// G-buffer coverage: 1 where a surface is seen.
std::vector<std::uint8_t> coverage(const CpuImage& gbuffer);
// One layer of a float surface, row-major.
std::vector<float> layer(const CpuImage& s, int l);

}  // namespace diptych::cli
