#pragma once
// A recipe names the passes of a frame, their parameters and connections, and the outputs
// wanted. JSON form (samples/graphs/*.json, documented in docs/frame-graph.md):
// {"passes": [{"name": "shadows", "type": "rt_shadows", "params": {...},
//              "inputs": {"hits": "gbuffer.hits"}}, ...],
//  "outputs": ["shade.color"]}
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace diptych {

struct RecipePass {
  std::string name, type;
  nlohmann::json params = nlohmann::json::object();
  std::map<std::string, std::string> inputs;  // slot -> "producer.output"
  std::string place;                          // "passes[2]", for errors
};

struct Recipe {
  std::string file = "<recipe>";  // for errors
  std::vector<RecipePass> passes;
  std::vector<std::string> outputs;  // "pass.output"
};

Recipe parseRecipe(const nlohmann::json& json, const std::string& file);
Recipe loadRecipe(const std::filesystem::path& path);

// Splits "pass.output" (at the first '.'); throws InputError naming `file`/`place` if malformed.
std::pair<std::string, std::string> splitResourceName(const std::string& name,
                                                      const std::string& file,
                                                      const std::string& place);

}  // namespace diptych
