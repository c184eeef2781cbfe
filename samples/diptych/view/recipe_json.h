#pragma once
// A recipe written back as the JSON that loadRecipe reads (docs/frame-graph.md), so that the
// viewer's current configuration runs unchanged in `diptych render --recipe` and `compare`.
#include <nlohmann/json.hpp>

#include "engine/graph/recipe.h"

namespace diptych::view {
nlohmann::json recipeToJson(const Recipe& recipe);
}  // namespace diptych::view
