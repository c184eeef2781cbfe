#pragma once
#include "engine/graph/recipe.h"
#include "engine/graph/registry.h"

namespace diptych {
// Every built-in pass type, registered once (passes/registry.cpp: one entry per type, naming
// its technique slot; the parameters come from the class's schema()).
const PassRegistry& builtinPasses();
// The default hybrid frame: samples/graphs/hybrid.json, compiled in (default_recipe.cpp.in).
Recipe defaultHybridRecipe();
}  // namespace diptych
