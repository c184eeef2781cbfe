#pragma once
#include "engine/graph/recipe.h"
#include "engine/graph/registry.h"

namespace diptych {
// Every built-in pass type, registered once (passes/registry.cpp: one line per pass).
const PassRegistry& builtinPasses();
// The default hybrid frame as a C++ recipe (samples/graphs/hybrid.json is the same graph).
Recipe defaultHybridRecipe();
}  // namespace diptych
