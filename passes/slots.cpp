#include "passes/slots.h"

#include <algorithm>
#include <charconv>

#include "engine/core/check.h"
#include "engine/core/error.h"
#include "engine/core/known.h"

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

const std::vector<TechniqueSlot>& techniqueSlots() {
  static const std::vector<TechniqueSlot> slots = {
      {.name = "visibility",
       .signal = "visibility",
       .format = Format::R32F,
       .layerPerLight = true,
       .fallback = vec4(1.f),
       .shadeInput = "light_visibility",
       .need = SceneNeed::ShadowCastingLight,
       .exact = "rt_shadows",
       .raster = "shadow_map:resolution=2048,bias=slope,factor=2,units=2,filter=pcf,kernel=3",
       .meaning = "V_i in [0,1] at the G-buffer point, one layer per scene light (1 = lit)"},
      {.name = "reflection",
       .signal = "reflection",
       .format = Format::RGBA32F,
       .layerPerLight = false,
       .fallback = vec4(0.f),
       .shadeInput = "reflection",
       .need = SceneNeed::ReflectiveMaterial,
       .exact = "rt_reflection",
       .raster = "env_cube",
       .meaning = "L_refl: radiance arriving at the G-buffer point along r = reflect(-v, "
                  "n_shading) (alpha 1), or a glTF lobe's prefiltered radiance (alpha 2); 0 "
                  "where the material's model has no reflection"},
      {.name = "transmission",
       .signal = "transmission",
       .format = Format::RGBA32F,
       .layerPerLight = false,
       .fallback = vec4(0.f),
       .shadeInput = "transmission",
       .need = SceneNeed::TransmissiveMaterial,
       .exact = "rt_transmission",
       .raster = "sorted_blend",
       .meaning = "L_trans: radiance arriving through the surface (refracted for ray tracing, "
                  "along the view ray for blending), after any volume attenuation; 0 where the "
                  "material's model has no transmission"},
      {.name = "texture_filtering",
       .signal = "albedo",
       .format = Format::RGBA32F,
       .layerPerLight = false,
       .fallback = vec4(-1.f),
       .shadeInput = "albedo",
       .need = SceneNeed::TexturedMaterial,
       .exact = "texture_supersample",
       .raster = "texture_trilinear",
       .meaning = "C and coverage: material colour x filtered colour texture (linear), alpha; -1 "
                  "where shade keeps its own level-0 lookup"},
  };
  return slots;
}

std::vector<std::string> techniqueSlotNames() {
  std::vector<std::string> out;
  for (const TechniqueSlot& s : techniqueSlots()) out.push_back(s.name);
  return out;
}

const TechniqueSlot* findTechniqueSlot(const std::string& name) {
  for (const TechniqueSlot& s : techniqueSlots())
    if (s.name == name) return &s;
  return nullptr;
}

void checkVisibilitySignal(const CpuImage& out, int w, int h, std::size_t lights,
                           const std::string& pass) {
  DIPTYCH_CHECK(out.channels() == 1 && out.desc.width == w && out.desc.height == h &&
                    out.desc.layers >= int(lights),
                pass + ": visibility is not R32F of the frame's size with a layer per light");
}

SlotIo slotIo(PassBuilder& b, const std::string& name) {
  const TechniqueSlot* slot = findTechniqueSlot(name);
  if (!slot) throw Error("slotIo: no technique slot '" + name + "' (passes/slots.cpp)");
  b.needs(slot->need);
  SlotIo io;
  io.hits = b.read(kHits, Format::RGBA32UI);
  const int layers = slot->layerPerLight ? std::max<int>(1, int(b.scene().lights.size())) : 1;
  io.signal = b.write(slot->signal, {slot->format, b.frame().width, b.frame().height, layers},
                      slot->fallback);
  return io;
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
  const TechniqueSlot* slot = findTechniqueSlot(o.slot);
  if (!slot) throw InputError("--slot", o.text, unknownName("slot", o.slot, techniqueSlotNames()));
  if (!registry.find(o.type))
    throw InputError("--slot", o.text, unknownName("pass type", o.type, registry.names()));
  RecipePass* shade = findPassOfType(recipe, "shade");
  if (!shade) throw InputError(recipe.file, "passes", "--slot needs a recipe with a 'shade' pass");
  auto input = shade->inputs.find(slot->shadeInput);
  if (input != shade->inputs.end()) {
    const auto [producer, output] = splitResourceName(input->second, recipe.file, shade->place);
    RecipePass* pass = findPass(recipe, producer);
    if (!pass)
      throw InputError(recipe.file, shade->place + ".inputs." + slot->shadeInput,
                       "--slot " + o.text + ": shade reads '" + input->second +
                           "', but the recipe has no pass named '" + producer + "'");
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
                   .inputs = {{kHits, gbuffer->name + "." + kHits}},
                   .place = "--slot " + o.text};
  const auto shadeIndex = shade - recipe.passes.data();
  recipe.passes.insert(recipe.passes.begin() + shadeIndex, std::move(added));
  recipe.passes[shadeIndex + 1].inputs[slot->shadeInput] = o.slot + "." + slot->signal;
}

}  // namespace diptych
