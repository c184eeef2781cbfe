#include "samples/diptych/view/recipe_json.h"

namespace diptych::view {

nlohmann::json recipeToJson(const Recipe& recipe) {
  nlohmann::json passes = nlohmann::json::array();
  for (const RecipePass& p : recipe.passes) {
    nlohmann::json pass = {{"name", p.name}, {"type", p.type}};
    if (!p.params.empty()) pass["params"] = p.params;
    if (!p.inputs.empty()) pass["inputs"] = p.inputs;
    passes.push_back(std::move(pass));
  }
  return {{"passes", passes}, {"outputs", recipe.outputs}};
}

}  // namespace diptych::view
