#include "engine/graph/export.h"

#include <fmt/format.h>

#include <algorithm>

#include "engine/core/timing.h"

namespace diptych {
namespace {}  // namespace

nlohmann::json timingStatsJson(const std::vector<double>& samples) {
  const TimingStats st = summarize(samples);
  return {{"median", st.median}, {"min", st.min}, {"max", st.max}, {"samples", st.samples}};
}

namespace {

// Every figure is a summary over the measured frames (median, min, max, sample count).
nlohmann::json timingJson(const NodeTiming& t) {
  nlohmann::json j;
  j["cpu_ms"] = timingStatsJson(t.cpuMs);
  if (!t.processCpuMs.empty()) j["process_cpu_ms"] = timingStatsJson(t.processCpuMs);
  if (!t.gpuMs.empty()) j["gpu_ms"] = timingStatsJson(t.gpuMs);
  if (!t.glWaitMs.empty()) j["gl_wait_ms"] = timingStatsJson(t.glWaitMs);
  if (!t.glWaitCpuMs.empty()) j["gl_wait_cpu_ms"] = timingStatsJson(t.glWaitCpuMs);
  if (!t.glCompletionMs.empty()) j["gl_completion_ms"] = timingStatsJson(t.glCompletionMs);
  if (!t.glCompletionCpuMs.empty())
    j["gl_completion_cpu_ms"] = timingStatsJson(t.glCompletionCpuMs);
  if (!t.glOverlapMs.empty()) j["gl_overlap_ms"] = timingStatsJson(t.glOverlapMs);
  for (const auto& [name, value] : t.counters) j["counters"][name] = value;
  return j;
}

bool isTransfer(const GraphNode& node) {
  return node.kind == NodeKind::Readback || node.kind == NodeKind::Upload;
}

std::string dotEscape(const std::string& s) {
  std::string out;
  for (char c : s) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return out;
}

}  // namespace

nlohmann::json graphToJson(const CompiledGraph& g, const std::vector<NodeTiming>* timings) {
  nlohmann::json j;
  j["recipe"] = g.recipeFile;
  j["frame"] = {{"width", g.frame.width}, {"height", g.frame.height}};
  j["passes"] = nlohmann::json::array();
  for (const GraphPass& p : g.passes) {
    nlohmann::json jp{
        {"name", p.name}, {"type", p.type}, {"domain", domainName(p.domain)}, {"culled", p.culled}};
    if (p.culled) jp["cull_reason"] = p.cullReason;
    if (!p.inputsLeftOut.empty()) jp["inputs_left_out"] = p.inputsLeftOut;
    if (!p.placement.empty()) jp["placement"] = p.placement;
    if (!p.variant.empty()) jp["variant"] = p.variant;
    for (SceneNeed n : p.needs) jp["scene_needs"].push_back(sceneNeedName(n));
    for (ResourceId r : p.reads) jp["reads"].push_back(g.resources[r].name);
    for (ResourceId w : p.writes) jp["writes"].push_back(g.resources[w].name);
    j["passes"].push_back(jp);
  }
  j["culled"] = nlohmann::json::array();
  for (const GraphPass& p : g.passes)
    if (p.culled) j["culled"].push_back({{"pass", p.name}, {"reason", p.cullReason}});
  j["resources"] = nlohmann::json::array();
  for (const GraphResource& r : g.resources) {
    nlohmann::json jr{{"name", r.name},
                      {"format", formatName(r.desc.format)},
                      {"width", r.desc.width},
                      {"height", r.desc.height},
                      {"layers", r.desc.layers},
                      {"bytes", r.desc.bytes()},
                      {"producer", g.passes[r.producer].name},
                      {"version", r.version}};
    if (r.previous != kNoResource) jr["modifies"] = g.resources[r.previous].name;
    j["resources"].push_back(jr);
  }
  j["schedule"] = nlohmann::json::array();
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    const GraphNode& node = g.nodes[n];
    nlohmann::json jn{{"index", n},
                      {"name", node.name},
                      {"kind", nodeKindName(node.kind)},
                      {"domain", domainName(node.domain)}};
    if (isTransfer(node)) {
      jn["resource"] = g.resources[node.resource].name;
      jn["from"] = domainName(node.kind == NodeKind::Readback ? Domain::Gl : Domain::Cpu);
      jn["to"] = domainName(node.domain);
      jn["bytes"] = g.resources[node.resource].desc.bytes();
      if (node.forOutputOnly) jn["for_output_only"] = true;
    }
    if (node.issuesGlWork() && node.kind != NodeKind::Readback) {
      // The CPU nodes that run while this node's GL work may still be going on: with GlSync
      // PerNode the executor waits for it before the next GL work or at the end of the frame
      // (with PerFrame the work may go on longer, beside later GL nodes too).
      jn["overlapped_by"] = nlohmann::json::array();
      for (std::size_t later = n + 1; later < g.nodes.size() && !g.nodes[later].issuesGlWork();
           ++later)
        jn["overlapped_by"].push_back(g.nodes[later].name);
    }
    if (timings && n < timings->size()) jn["timing"] = timingJson((*timings)[n]);
    j["schedule"].push_back(jn);
  }
  j["edges"] = nlohmann::json::array();
  for (const GraphResource& r : g.resources)
    for (PassIndex reader : r.readers)
      j["edges"].push_back({{"from", g.passes[r.producer].name},
                            {"to", g.passes[reader].name},
                            {"resource", r.name}});
  j["storages"] = nlohmann::json::array();
  for (const GraphStorage& s : g.storages)
    j["storages"].push_back({{"resource", g.resources[s.resource].name},
                             {"domain", domainName(s.domain)},
                             {"first_node", s.firstNode},
                             {"last_node", s.lastNode},
                             {"pool_slot", s.poolSlot.value},
                             {"bytes", s.desc.bytes()}});
  j["memory"] = {{"bytes_without_reuse", g.bytesWithoutReuse()},
                 {"bytes_with_reuse", g.bytesWithReuse()},
                 {"pool_slots", g.pool.size()},
                 {"storages", g.storages.size()}};
  for (ResourceId o : g.outputs) j["outputs"].push_back(g.resources[o].name);
  return j;
}

std::string graphToDot(const CompiledGraph& g, const std::vector<NodeTiming>* timings) {
  std::string dot = "digraph frame {\n  rankdir=LR;\n  node [fontname=\"Helvetica\"];\n";
  auto medianOf = [&](std::size_t n) {
    return timings && n < timings->size() ? summarize((*timings)[n].cpuMs).median : -1.0;
  };
  // Executed nodes: passes as boxes (GL filled), transfers and defaults as dotted ellipses.
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    const GraphNode& node = g.nodes[n];
    std::string label = dotEscape(node.name);  // escaped parts joined by DOT's \n
    std::string shape = "shape=ellipse, style=dotted";
    if (node.kind == NodeKind::Pass) {
      const GraphPass& pass = g.passes[node.pass];
      label += "\\n(" + dotEscape(pass.type) + ", " + domainName(pass.domain) + ")";
      shape = pass.domain == Domain::Gl ? "shape=box, style=filled" : "shape=box, style=rounded";
    } else if (isTransfer(node)) {
      label += fmt::format("\\n{} bytes", g.resources[node.resource].desc.bytes());
    }
    if (medianOf(n) >= 0) label += fmt::format("\\n{:.3f} ms", medianOf(n));
    dot += fmt::format("  \"{}\" [{}, label=\"{}\"];\n", dotEscape(node.name), shape, label);
  }
  // Culled passes, dashed, with the reason; their recipe edges are dashed too.
  for (const GraphPass& pass : g.passes) {
    if (!pass.culled) continue;
    dot += fmt::format("  \"{}\" [shape=box, style=dashed, label=\"{}\\n({})\\nculled: {}\"];\n",
                       dotEscape(pass.name), dotEscape(pass.name), dotEscape(pass.type),
                       dotEscape(pass.cullReason));
  }
  for (const GraphResource& r : g.resources) {
    for (PassIndex reader : r.readers) {
      if (!g.passes[r.producer].culled && !g.passes[reader].culled) continue;
      dot += fmt::format("  \"{}\" -> \"{}\" [style=dashed, label=\"{}\"];\n",
                         dotEscape(g.passes[r.producer].name), dotEscape(g.passes[reader].name),
                         dotEscape(r.name));
    }
  }
  // Executed edges: from the node that last wrote a storage to each node that reads it.
  std::vector<int> lastWriter(g.storages.size(), -1);
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    for (int s : g.nodes[n].storagesRead) {
      if (lastWriter[s] < 0) continue;
      const GraphStorage& st = g.storages[s];
      dot += fmt::format("  \"{}\" -> \"{}\" [label=\"{}\\n{}\"];\n",
                         dotEscape(g.nodes[lastWriter[s]].name), dotEscape(g.nodes[n].name),
                         dotEscape(g.resources[st.resource].name), dotEscape(describe(st.desc)));
    }
    for (int s : g.nodes[n].storagesWritten) lastWriter[s] = int(n);
  }
  dot += fmt::format("  label=\"pool: {} bytes with reuse, {} without\";\n}}\n", g.bytesWithReuse(),
                     g.bytesWithoutReuse());
  return dot;
}

namespace {

// The nodes whose first use is shown (above kFirstUseShownMs), largest first.
std::vector<std::size_t> shownFirstUse(const GraphExecutor::MeasuredRun& run) {
  std::vector<std::size_t> order;
  for (std::size_t n = 0; n < run.firstUseMs.size(); ++n)
    if (run.firstUseMs[n] > kFirstUseShownMs) order.push_back(n);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return run.firstUseMs[a] > run.firstUseMs[b]; });
  return order;
}

}  // namespace

nlohmann::json firstFrameJson(const CompiledGraph& graph, const GraphExecutor::MeasuredRun& run) {
  nlohmann::json byNode = nlohmann::json::object();
  for (std::size_t n : shownFirstUse(run)) byNode[graph.nodes[n].name] = run.firstUseMs[n];
  return {{"wall_ms", run.firstFrameMs},
          {"one_time_ms", run.firstFrameOneTimeMs},
          {"steady_ms", run.steadyFrameMs},
          {"unrecorded_ms", run.firstFrameUnrecordedMs()},
          {"first_use_ms", byNode}};
}

std::string firstFrameLine(const CompiledGraph& graph, const GraphExecutor::MeasuredRun& run) {
  std::string line = fmt::format(
      "first frame: {:.1f} ms against a steady {:.1f} ms: {:.1f} ms one-time work (listed above), "
      "{:.1f} ms first-use work recorded nowhere else",
      run.firstFrameMs, run.steadyFrameMs, run.firstFrameOneTimeMs, run.firstFrameUnrecordedMs());
  const std::vector<std::size_t> order = shownFirstUse(run);
  for (std::size_t i = 0; i < order.size(); ++i)
    line += fmt::format("{} {} {:.1f}", i == 0 ? " (by node:" : ",", graph.nodes[order[i]].name,
                        run.firstUseMs[order[i]]);
  if (!order.empty()) line += ")";
  // What it is, where it is known to come from (docs/frame-graph.md, "One-time costs").
  return line +
         ": a GL driver compiling programs at their first draw (llvmpipe; Mesa's shader "
         "cache keeps them for the next run), first-touch memory, cold caches; in no frame "
         "median";
}

}  // namespace diptych
