#include "samples/diptych/compare/runner.h"

#include "engine/core/timing.h"
#include "passes/registry.h"
#include "passes/slots.h"

namespace diptych::cli {

GraphRun runGraph(const Recipe& recipe, RenderWorld& world, const FrameSettings& frame,
                  const std::vector<std::string>& outputs, int warmup, int frames) {
  GraphRun run;
  run.graph = compileGraph(recipe, builtinPasses(), world.scene(), frame, outputs);
  GraphExecutor ex(run.graph, world);
  for (int f = 0; f < warmup + frames; ++f) {
    if (f == warmup) ex.clearTimings();
    ex.runFrame();
    if (f == 0)
      for (const NodeTiming& t : ex.timings())
        if (!t.cpuMs.empty()) run.firstFrameMs += t.cpuMs.back();
  }
  run.timings = ex.timings();
  for (std::size_t n = 0; n < run.graph.nodes.size(); ++n) {
    const double ms = summarize(run.timings[n].cpuMs).median;
    run.passMs[run.graph.nodes[n].name] = ms;
    run.totalMs += ms;
    if (auto it = run.timings[n].counters.find("rays"); it != run.timings[n].counters.end())
      run.rays += it->second;
  }
  for (ResourceId id : run.graph.outputs) {
    const std::string& name = run.graph.resources[id].name;
    run.outputs[name] = ex.output(name);
  }
  return run;
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
