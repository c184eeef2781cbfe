#include "engine/graph/export.h"

#include <fmt/format.h>

#include "engine/core/timing.h"

namespace diptych {
namespace {

nlohmann::json timingJson(const NodeTiming& t) {
  nlohmann::json j;
  const TimingStats cpu = summarize(t.cpuMs);
  j["cpu_ms"] = {
      {"median", cpu.median}, {"min", cpu.min}, {"max", cpu.max}, {"samples", cpu.samples}};
  if (!t.gpuMs.empty()) {
    const TimingStats gpu = summarize(t.gpuMs);
    j["gpu_ms"] = {
        {"median", gpu.median}, {"min", gpu.min}, {"max", gpu.max}, {"samples", gpu.samples}};
  }
  for (const auto& [name, value] : t.counters) j["counters"][name] = value;
  return j;
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
    if (timings && n < timings->size()) jn["timing"] = timingJson((*timings)[n]);
    j["schedule"].push_back(jn);
  }
  j["edges"] = nlohmann::json::array();
  for (const GraphResource& r : g.resources)
    for (int reader : r.readers)
      j["edges"].push_back({{"from", g.passes[r.producer].name},
                            {"to", g.passes[reader].name},
                            {"resource", r.name}});
  j["storages"] = nlohmann::json::array();
  for (const GraphStorage& s : g.storages)
    j["storages"].push_back({{"resource", g.resources[s.resource].name},
                             {"domain", domainName(s.domain)},
                             {"first_node", s.firstNode},
                             {"last_node", s.lastNode},
                             {"pool_slot", s.poolSlot},
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
  std::vector<double> medians(g.nodes.size(), -1.0);
  if (timings)
    for (std::size_t n = 0; n < g.nodes.size() && n < timings->size(); ++n)
      medians[n] = summarize((*timings)[n].cpuMs).median;
  auto nodeIndexOfPass = [&](int pass) {
    for (std::size_t n = 0; n < g.nodes.size(); ++n)
      if (g.nodes[n].kind == NodeKind::Pass && g.nodes[n].pass == pass) return int(n);
    return -1;
  };
  for (std::size_t p = 0; p < g.passes.size(); ++p) {
    const GraphPass& pass = g.passes[p];
    std::string label = pass.name + "\\n(" + pass.type + ", " + domainName(pass.domain) + ")";
    if (pass.culled) label += "\\nculled: " + pass.cullReason;
    const int n = nodeIndexOfPass(int(p));
    if (n >= 0 && medians[n] >= 0) label += fmt::format("\\n{:.3f} ms", medians[n]);
    dot += fmt::format("  \"{}\" [shape=box, style=\"{}\", label=\"{}\"];\n", dotEscape(pass.name),
                       pass.culled ? "dashed" : (pass.domain == Domain::Gl ? "filled" : "rounded"),
                       dotEscape(label));
  }
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    const GraphNode& node = g.nodes[n];
    if (node.kind == NodeKind::Pass) continue;
    std::string label = node.name;
    if (medians[n] >= 0) label += fmt::format("\\n{:.3f} ms", medians[n]);
    dot += fmt::format("  \"{}\" [shape=ellipse, style=dotted, label=\"{}\"];\n",
                       dotEscape(node.name), dotEscape(label));
  }
  for (const GraphResource& r : g.resources) {
    const std::string edgeLabel = r.name + "\\n" + describe(r.desc);
    for (int reader : r.readers)
      dot +=
          fmt::format("  \"{}\" -> \"{}\" [label=\"{}\"];\n", dotEscape(g.passes[r.producer].name),
                      dotEscape(g.passes[reader].name), dotEscape(edgeLabel));
  }
  dot += fmt::format("  label=\"pool: {} bytes with reuse, {} without\";\n}}\n", g.bytesWithReuse(),
                     g.bytesWithoutReuse());
  return dot;
}

}  // namespace diptych
