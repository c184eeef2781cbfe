#include "samples/diptych/compare/runner.h"

#include <unistd.h>

#include <bit>
#include <cstdint>
#include <cstdio>

#include "engine/core/error.h"
#include "engine/core/timing.h"
#include "engine/graph/export.h"
#include "passes/registry.h"
#include "passes/slots.h"

namespace diptych::cli {

GraphRun runGraph(const Recipe& recipe, RenderWorld& world, const FrameSettings& frame,
                  const std::vector<std::string>& outputs, int warmup, int frames) {
  return runCompiled(compileGraph(recipe, builtinPasses(), world.scene(), frame, outputs), world,
                     outputs, warmup, frames);
}

GraphRun runCompiled(CompiledGraph graph, RenderWorld& world,
                     const std::vector<std::string>& outputs, int warmup, int frames) {
  GraphRun run;
  run.graph = std::move(graph);
  GraphExecutor ex(run.graph, world);
  const GraphExecutor::MeasuredRun measured = ex.runMeasured(warmup, frames);
  run.firstFrameMs = measured.firstFrameMs;
  run.firstFrame = firstFrameJson(run.graph, measured);
  run.oneTimeMs = measured.oneTimeMs;
  run.timings = ex.timings();
  run.glSync = ex.glSyncReason();
  // GlSync::PerFrame: the frame's GL work completes in one wait at its end.
  if (!ex.frameGlWaitMs().empty()) run.totalMs += summarize(ex.frameGlWaitMs()).median;
  for (std::size_t n = 0; n < run.graph.nodes.size(); ++n) {
    const NodeTiming& t = run.timings[n];
    const double ms = summarize(t.cpuMs).median;
    // GL timer queries are not waited on per node (executor.cpp): a GL pass's CPU time is the
    // time to issue its commands (on llvmpipe that includes vertex processing and binning on
    // the calling thread) and its GL time the rest, so its figure is their sum; a transfer's
    // figure is its own GL time. The wait for earlier nodes' GL work is kept out of every
    // node's CPU time (glWaitMs, and glCompletionMs of the node that issued it); the frame total
    // adds it back once (docs/frame-graph.md).
    const GraphNode& node = run.graph.nodes[n];
    const bool transfer = node.kind != NodeKind::Pass;
    const double gl = t.gpuMs.empty() ? 0.0 : summarize(t.gpuMs).median;
    run.passMs[node.name] = t.gpuMs.empty() ? ms : transfer ? gl : ms + gl;
    // Readbacks of signals requested only for the per-slot metrics are measurement, not frame
    // work: the frame's own output (outputs[0], the image) still counts.
    const bool measurementOnly = node.forOutputOnly && !outputs.empty() &&
                                 run.graph.resources[node.resource].name != outputs.front();
    // The wait for a node's GL work to complete (before the next GL node or at the frame's end)
    // is frame work, measured or not: it always counts.
    run.totalMs += t.glCompletionMs.empty() ? 0.0 : summarize(t.glCompletionMs).median;
    if (!measurementOnly) run.totalMs += ms;
    if (auto it = run.timings[n].counters.find("rays"); it != run.timings[n].counters.end())
      run.rays += it->second;
  }
  for (ResourceId id : run.graph.outputs) {
    const std::string& name = run.graph.resources[id].name;
    run.outputs[name] = ex.output(name);
  }
  return run;
}

GraphRun runAccumulated(const Recipe& recipe, std::span<const std::unique_ptr<RenderWorld>> worlds,
                        const FrameSettings& frame, const std::vector<std::string>& outputs,
                        int warmup, int frames) {
  GraphRun total;
  for (std::size_t k = 0; k < worlds.size(); ++k) {
    GraphRun run = runGraph(recipe, *worlds[k], frame, {outputs.front()}, warmup, frames);
    const CpuImage& image = run.outputs.at(outputs.front());
    if (image.desc.format != Format::RGBA32F)
      throw Error("the accumulation buffer averages RGBA32F images; " + outputs.front() +
                  " is not one");
    if (k == 0) {
      total = std::move(run);
      continue;
    }
    CpuImage& sum = total.outputs.at(outputs.front());
    for (std::size_t w = 0; w < sum.words.size(); ++w)
      sum.words[w] = std::bit_cast<std::uint32_t>(std::bit_cast<float>(sum.words[w]) +
                                                  std::bit_cast<float>(image.words[w]));
    total.totalMs += run.totalMs;
    total.firstFrameMs += run.firstFrameMs;
    total.rays += run.rays;
    for (const auto& [node, ms] : run.passMs.items())
      total.passMs[node] = total.passMs.value(node, 0.0) + ms.get<double>();
    for (const auto& [what, ms] : run.oneTimeMs) total.oneTimeMs[what] += ms;
  }
  if (worlds.size() > 1) {
    CpuImage& sum = total.outputs.at(outputs.front());
    const float scale = 1.f / float(worlds.size());
    for (std::uint32_t& w : sum.words)
      w = std::bit_cast<std::uint32_t>(std::bit_cast<float>(w) * scale);
  }
  return total;
}

// One line of progress: a bar on a terminal, a plain line otherwise (logs, CI).
void progress(const char* label, int done, int total, const std::string& what) {
  if (isatty(fileno(stderr))) {
    const int width = 30, filled = total ? width * done / total : width;
    std::fprintf(stderr, "\r[%s%s] %d/%d %-40.40s", std::string(filled, '#').c_str(),
                 std::string(width - filled, '.').c_str(), done, total, what.c_str());
    if (done == total) std::fputc('\n', stderr);
  } else {
    std::fprintf(stderr, "%s: %d/%d %s\n", label, done, total, what.c_str());
  }
  std::fflush(stderr);
}

std::vector<std::uint8_t> coverage(const CpuImage& gbuffer) {
  std::vector<std::uint8_t> mask(std::size_t(gbuffer.desc.width) * gbuffer.desc.height);
  for (int y = 0; y < gbuffer.desc.height; ++y)
    for (int x = 0; x < gbuffer.desc.width; ++x)
      mask[std::size_t(y) * gbuffer.desc.width + x] = gbuffer.u(x, y, 0) != 0u;
  return mask;
}

std::vector<float> layer(const CpuImage& s, int l) {
  std::vector<float> v(std::size_t(s.desc.width) * s.desc.height);
  for (int y = 0; y < s.desc.height; ++y)
    for (int x = 0; x < s.desc.width; ++x) v[std::size_t(y) * s.desc.width + x] = s.f(x, y, 0, l);
  return v;
}

std::string slotSignal(const Recipe& recipe, const std::string& slot) {
  const TechniqueSlot* info = findTechniqueSlot(slot);
  if (!info) return "";
  for (const RecipePass& p : recipe.passes)
    if (p.type == "shade")
      if (auto it = p.inputs.find(info->shadeInput); it != p.inputs.end()) return it->second;
  return "";
}

}  // namespace diptych::cli
