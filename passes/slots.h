#pragma once
// Technique slots (docs/technique-slots.md), declared once here: each slot's signal (name,
// format, layer rule, fallback), the shade input it feeds, the scene need that culls its
// producers, its exact producer and the raster approximation compare's "raster" variant uses.
// Producers register against a slot by name (passes/registry.cpp) and declare their G-buffer
// input and signal output with slotIo(). Adding a slot is one entry in techniqueSlots() plus
// its shade input. Also: the command-line override `--slot SLOT=TYPE[:key=value,...]`.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/graph/pass.h"
#include "engine/graph/recipe.h"
#include "engine/graph/registry.h"

namespace diptych {

// The G-buffer's hit ids (RGBA32UI: instance + 1, primitive, floatBits(u), floatBits(v)): the
// gbuffer pass's output and the input name of every pass that reads it.
inline constexpr const char* kHits = "hits";

struct TechniqueSlot {
  std::string name;        // "visibility"
  std::string signal;      // the producers' output: "visibility"
  Format format;           // R32F
  bool layerPerLight;      // one layer per scene light (at least one), else one layer
  vec4 fallback;           // what shade reads when the producer is culled
  std::string shadeInput;  // "light_visibility"
  SceneNeed need;          // a scene without it culls the producer
  std::string exact;       // the exact producer's pass type: "rt_shadows"
  std::string raster;      // compare's all-raster variant: "TYPE[:key=value,...]"
  std::string meaning;     // one line for docs and `diptych passes`
};
const std::vector<TechniqueSlot>& techniqueSlots();
std::vector<std::string> techniqueSlotNames();
// nullptr when no slot has that name.
const TechniqueSlot* findTechniqueSlot(const std::string& name);

// What a producer's setup shares: the slot's scene need, the G-buffer hits input and the
// signal output at frame size with the slot's format, layers and fallback.
struct SlotIo {
  ResourceId hits = kNoResource, signal = kNoResource;
};
SlotIo slotIo(PassBuilder& builder, const std::string& slot);
// A CPU visibility producer's output as its row writes assume: R32F of the frame's w x h, a
// layer per light (at least). Throws Error naming the pass otherwise.
void checkVisibilitySignal(const CpuImage& out, int w, int h, std::size_t lights,
                           const std::string& pass);

struct SlotOverride {
  std::string slot, type;
  nlohmann::json params = nlohmann::json::object();
  std::string text;  // as given, for errors
};

// Parses "visibility=shadow_map:bias=slope,factor=2". Values: numbers, true/false, or strings.
// Throws InputError naming the option text.
SlotOverride parseSlotOverride(const std::string& text);

// Replaces the type and parameters of the pass feeding the slot's shade input, or adds a
// producer named after the slot (reading the G-buffer pass's hits) when there is none.
// The pass type must exist; its parameters are checked when the recipe is compiled.
void applySlotOverride(Recipe& recipe, const SlotOverride& override, const PassRegistry& registry);

}  // namespace diptych
