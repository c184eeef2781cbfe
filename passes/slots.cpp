#include "passes/slots.h"

#include <algorithm>
#include <charconv>

#include "engine/core/error.h"

namespace diptych {
namespace {

nlohmann::json parseValue(const std::string& v) {
  if (v == "true") return true;
  if (v == "false") return false;
  double d = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), d);
  if (ec == std::errc() && end == v.data() + v.size()) return d;
  return v;
}

RecipePass* findPass(Recipe& r, const std::string& name) {
  for (RecipePass& p : r.passes)
    if (p.name == name) return &p;
  return nullptr;
}

RecipePass* findPassOfType(Recipe& r, const std::string& type) {
  for (RecipePass& p : r.passes)
    if (p.type == type) return &p;
  return nullptr;
}

}  // namespace

const std::vector<SlotInfo>& techniqueSlots() {
  static const std::vector<SlotInfo> slots = {
      {"visibility", "light_visibility", "visibility"},
      {"reflection", "reflection", "reflection"},
      {"transmission", "transmission", "transmission"},
  };
  return slots;
}

SlotOverride parseSlotOverride(const std::string& text) {
  auto fail = [&](const std::string& message) {
    throw InputError("--slot", text, message + " (expected SLOT=TYPE[:key=value,...])");
  };
  SlotOverride o;
  o.text = text;
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) fail("missing SLOT=");
  o.slot = text.substr(0, eq);
  const std::string rest = text.substr(eq + 1);
  const auto colon = rest.find(':');
  o.type = rest.substr(0, colon);
  if (o.type.empty()) fail("missing pass type");
  if (colon != std::string::npos) {
    std::string params = rest.substr(colon + 1);
    std::size_t start = 0;
    while (start <= params.size()) {
      const std::size_t comma = std::min(params.find(',', start), params.size());
      const std::string item = params.substr(start, comma - start);
      const auto keq = item.find('=');
      if (keq == std::string::npos || keq == 0 || keq + 1 == item.size())
        fail("parameter '" + item + "' is not key=value");
      o.params[item.substr(0, keq)] = parseValue(item.substr(keq + 1));
      start = comma + 1;
    }
  }
  return o;
}

void applySlotOverride(Recipe& recipe, const SlotOverride& o, const PassRegistry& registry) {
  const auto& slots = techniqueSlots();
  const auto slot =
      std::find_if(slots.begin(), slots.end(), [&](const SlotInfo& s) { return s.slot == o.slot; });
  if (slot == slots.end())
    throw InputError("--slot", o.text,
                     "unknown slot '" + o.slot + "' (slots: visibility, reflection, transmission)");
  if (!registry.find(o.type)) {
    std::string known;
    for (const std::string& n : registry.names()) known += (known.empty() ? "" : ", ") + n;
    throw InputError("--slot", o.text, "unknown pass type '" + o.type + "' (known: " + known + ")");
  }
  RecipePass* shade = findPassOfType(recipe, "shade");
  if (!shade) throw InputError(recipe.file, "passes", "--slot needs a recipe with a 'shade' pass");
  auto input = shade->inputs.find(slot->shadeInput);
  if (input != shade->inputs.end()) {
    const auto [producer, output] = splitResourceName(input->second, recipe.file, shade->place);
    RecipePass* pass = findPass(recipe, producer);
    pass->type = o.type;
    pass->params = o.params;
    pass->place = "--slot " + o.text + " (" + pass->place + ")";
    if (output != slot->signal) input->second = producer + "." + slot->signal;
    return;
  }
  const RecipePass* gbuffer = findPassOfType(recipe, "gbuffer");
  if (!gbuffer)
    throw InputError(recipe.file, "passes", "--slot needs a recipe with a 'gbuffer' pass");
  if (findPass(recipe, o.slot))
    throw InputError(recipe.file, "passes",
                     "a pass is already named '" + o.slot + "' but does not feed shade's '" +
                         slot->shadeInput + "'");
  RecipePass added{.name = o.slot,
                   .type = o.type,
                   .params = o.params,
                   .inputs = {{"visibility", gbuffer->name + ".visibility"}},
                   .place = "--slot " + o.text};
  const std::string gbufferName = gbuffer->name;
  const auto shadeIndex = shade - recipe.passes.data();
  recipe.passes.insert(recipe.passes.begin() + shadeIndex, std::move(added));
  recipe.passes[shadeIndex + 1].inputs[slot->shadeInput] = o.slot + "." + slot->signal;
}

}  // namespace diptych
