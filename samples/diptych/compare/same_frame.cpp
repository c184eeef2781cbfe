#include "samples/diptych/compare/same_frame.h"

#include "engine/graph/scene_needs.h"

namespace diptych::cli {
namespace {

// The recipe's parameters with the schema's defaults filled in: "resolution" left out and
// "resolution": 2048 written out (the default) are the same pass.
nlohmann::json resolvedParams(const RecipePass& spec, const PassRegistry& registry) {
  nlohmann::json out = spec.params.is_object() ? spec.params : nlohmann::json::object();
  if (const PassTypeInfo* type = registry.find(spec.type))
    for (const ParamSpec& p : type->params)
      if (!out.contains(p.name)) out[p.name] = p.fallback;
  return out;
}

const RecipePass* recipePass(const Recipe& recipe, const std::string& name) {
  for (const RecipePass& p : recipe.passes)
    if (p.name == name) return &p;
  return nullptr;
}

nlohmann::json resourceJson(const CompiledGraph& g, ResourceId id) {
  const GraphResource& r = g.resources[id];
  return {{"name", r.name}, {"desc", describe(r.desc)}};
}

}  // namespace

FrameIdentity frameIdentity(const CompiledGraph& graph, const Recipe& recipe,
                            const PassRegistry& registry, const nlohmann::json& sceneState,
                            const std::string& askedDetail) {
  FrameIdentity id;
  id.askedDetail = askedDetail;
  nlohmann::json live = nlohmann::json::array();
  id.passes = nlohmann::json::object();
  for (const GraphPass& p : graph.passes) {
    const RecipePass* spec = recipePass(recipe, p.name);
    const nlohmann::json params = spec ? resolvedParams(*spec, registry) : nlohmann::json::object();
    id.passes[p.name] = {
        {"type", p.type}, {"params", params}, {"culled", p.culled}, {"reason", p.cullReason}};
    if (p.culled) continue;
    nlohmann::json jp = {{"name", p.name},
                         {"type", p.type},
                         {"domain", domainName(p.domain)},
                         {"params", params},
                         {"inputs_left_out", p.inputsLeftOut},
                         {"placement", p.placement},
                         {"variant", p.variant},
                         {"reads", nlohmann::json::array()},
                         {"writes", nlohmann::json::array()},
                         {"needs", nlohmann::json::array()}};
    for (ResourceId r : p.reads) jp["reads"].push_back(resourceJson(graph, r));
    for (ResourceId r : p.glOnlyReads) jp["gl_only_reads"].push_back(resourceJson(graph, r));
    for (ResourceId w : p.writes) jp["writes"].push_back(resourceJson(graph, w));
    for (SceneNeed n : p.needs) jp["needs"].push_back(sceneNeedName(n));
    live.push_back(jp);
  }
  nlohmann::json schedule = nlohmann::json::array();
  for (const GraphNode& node : graph.nodes) {
    nlohmann::json jn = {{"kind", nodeKindName(node.kind)},
                         {"name", node.name},
                         {"domain", domainName(node.domain)}};
    if (node.kind != NodeKind::Pass) {
      const GraphResource& r = graph.resources[node.resource];
      jn["resource"] = resourceJson(graph, node.resource);
      // A default fill writes the producer's declared fallback: part of the frame.
      jn["fallback"] = {r.fallback.x, r.fallback.y, r.fallback.z, r.fallback.w};
      jn["for_output_only"] = node.forOutputOnly;
    }
    schedule.push_back(jn);
  }
  nlohmann::json outputs = nlohmann::json::array();
  for (ResourceId o : graph.outputs) outputs.push_back(resourceJson(graph, o));
  id.signature = {{"scene", sceneState},
                  {"frame", {graph.frame.width, graph.frame.height}},
                  {"passes", live},
                  {"schedule", schedule},
                  {"outputs", outputs}};
  return id;
}

std::string sameFrameReason(const FrameIdentity& mine, const FrameIdentity& earlier) {
  std::string reason;
  auto add = [&](const std::string& pass, const nlohmann::json& culled) {
    reason +=
        (reason.empty() ? "" : "; ") + pass + " culled: " + culled["reason"].get<std::string>();
  };
  for (const auto& [name, p] : mine.passes.items()) {
    const bool same = earlier.passes.contains(name) && earlier.passes[name]["type"] == p["type"] &&
                      earlier.passes[name]["params"] == p["params"];
    if (same) continue;
    // Equal signatures: a pass the two recipes set differently is culled in both frames.
    if (p["culled"].get<bool>()) add(name, p);
  }
  for (const auto& [name, p] : earlier.passes.items())
    if (!mine.passes.contains(name) && p["culled"].get<bool>()) add(name, p);
  // Equal signatures hold the same scene state: a detail asked differently changed nothing.
  if (mine.askedDetail != earlier.askedDetail)
    reason += (reason.empty() ? "" : "; ") + std::string("surface_detail ") +
              (mine.askedDetail.empty() ? earlier.askedDetail : mine.askedDetail) +
              ": the scene as authored";
  return reason.empty() ? "the same compiled graph" : reason;
}

}  // namespace diptych::cli
