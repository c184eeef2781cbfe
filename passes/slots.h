#pragma once
// Technique slots (docs/technique-slots.md): which shade input each slot feeds, and the
// command-line override `--slot SLOT=TYPE[:key=value,...]` applied to a recipe.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/graph/recipe.h"
#include "engine/graph/registry.h"

namespace diptych {

struct SlotInfo {
  std::string slot;        // "visibility"
  std::string shadeInput;  // "light_visibility"
  std::string signal;      // the producer's output name: "visibility"
};
const std::vector<SlotInfo>& techniqueSlots();

struct SlotOverride {
  std::string slot, type;
  nlohmann::json params = nlohmann::json::object();
  std::string text;  // as given, for errors
};

// Parses "visibility=shadow_map:bias=slope,factor=2". Values: numbers, true/false, or strings.
// Throws InputError naming the option text.
SlotOverride parseSlotOverride(const std::string& text);

// Replaces the type and parameters of the pass feeding the slot's shade input, or adds a
// producer named after the slot (reading the G-buffer pass's visibility) when there is none.
// The pass type must exist; its parameters are checked when the recipe is compiled.
void applySlotOverride(Recipe& recipe, const SlotOverride& override, const PassRegistry& registry);

}  // namespace diptych
