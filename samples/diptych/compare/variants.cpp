#include "samples/diptych/compare/variants.h"

#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/input_file.h"
#include "engine/core/json_text.h"
#include "passes/registry.h"
#include "passes/slots.h"

namespace diptych::cli {

Recipe Variant::build(const PassRegistry& registry) const {
  Recipe recipe = recipeFile.empty() ? defaultHybridRecipe() : loadRecipe(recipeFile);
  for (const std::string& s : slots) applySlotOverride(recipe, parseSlotOverride(s), registry);
  return recipe;
}

std::vector<Variant> defaultVariants(const PassRegistry& registry) {
  // Every slot's producers, each swapped alone into the all-exact hybrid so that its error is
  // that of one term; plus an all-raster frame. Types not registered in this build are skipped.
  const std::vector<std::pair<std::string, std::vector<std::string>>> candidates = {
      {"hybrid-exact", {}},
      {"raster",
       {"visibility=shadow_map:resolution=2048,bias=slope,factor=2,units=2,filter=pcf,kernel=3",
        "reflection=env_cube", "transmission=sorted_blend"}},
      {"shadow-map-256-none", {"visibility=shadow_map:resolution=256,bias=none"}},
      {"shadow-map-1024-constant", {"visibility=shadow_map:resolution=1024,bias=constant"}},
      {"shadow-map-2048-slope",
       {"visibility=shadow_map:resolution=2048,bias=slope,factor=2,units=2"}},
      {"shadow-map-2048-normal-offset",
       {"visibility=shadow_map:resolution=2048,bias=normal_offset"}},
      {"shadow-map-2048-receiver-plane-pcf",
       {"visibility=shadow_map:resolution=2048,bias=receiver_plane,filter=pcf,kernel=3"}},
      {"shadow-map-2048-adaptive", {"visibility=shadow_map:resolution=2048,bias=adaptive"}},
      {"shadow-map-4096-slope-pcss",
       {"visibility=shadow_map:resolution=4096,bias=slope,factor=2,units=2,filter=pcss"}},
      {"env-cube", {"reflection=env_cube"}},
      {"env-sphere", {"reflection=env_sphere"}},
      {"env-equirect", {"reflection=env_equirect"}},
      {"env-dynamic-cube", {"reflection=env_dynamic_cube"}},
      {"planar-mirror", {"reflection=planar_mirror"}},
      {"sorted-blend", {"transmission=sorted_blend"}},
      {"unsorted-blend", {"transmission=unsorted_blend"}},
  };
  std::vector<Variant> out;
  for (const auto& [name, slots] : candidates) {
    bool available = true;
    for (const std::string& s : slots)
      available = available && registry.find(parseSlotOverride(s).type);
    if (available) out.push_back({name, "", slots});
  }
  return out;
}

std::vector<Variant> loadVariants(const std::string& spec, const PassRegistry& registry) {
  if (std::filesystem::path(spec).extension() == ".json") {
    nlohmann::json j = parseJsonText(readInputFile(spec, kMaxJsonFileBytes), spec);
    if (!j.is_object() || !j.contains("variants") || !j["variants"].is_array() ||
        j["variants"].empty())
      throw InputError(spec, "variants", "expected a non-empty array");
    std::vector<Variant> out;
    std::set<std::string> names;
    const auto base = std::filesystem::path(spec).parent_path();
    for (std::size_t i = 0; i < j["variants"].size(); ++i) {
      const auto& v = j["variants"][i];
      const std::string place = "variants[" + std::to_string(i) + "]";
      if (!v.is_object() || !v.contains("name") || !v["name"].is_string())
        throw InputError(spec, place, "expected an object with a \"name\"");
      for (const auto& [key, value] : v.items())
        if (key != "name" && key != "recipe" && key != "slots")
          throw InputError(spec, place + "." + key, "unknown key");
      Variant variant{v["name"].get<std::string>(), "", {}};
      if (!names.insert(variant.name).second)
        throw InputError(spec, place + ".name", "duplicate variant name");
      if (v.contains("recipe")) {
        if (!v["recipe"].is_string()) throw InputError(spec, place + ".recipe", "expected a path");
        variant.recipeFile = (base / v["recipe"].get<std::string>()).string();
      }
      if (v.contains("slots")) {
        if (!v["slots"].is_array())
          throw InputError(spec, place + ".slots", "expected an array of SLOT=TYPE[:k=v]");
        for (const auto& s : v["slots"]) {
          if (!s.is_string()) throw InputError(spec, place + ".slots", "expected strings");
          parseSlotOverride(s.get<std::string>());
          variant.slots.push_back(s.get<std::string>());
        }
      }
      out.push_back(variant);
    }
    return out;
  }
  const std::vector<Variant> all = defaultVariants(registry);
  std::vector<Variant> out;
  std::size_t start = 0;
  while (start <= spec.size()) {
    const std::size_t comma = std::min(spec.find(',', start), spec.size());
    const std::string name = spec.substr(start, comma - start);
    auto it =
        std::find_if(all.begin(), all.end(), [&](const Variant& v) { return v.name == name; });
    if (it == all.end()) {
      std::string known;
      for (const Variant& v : all) known += (known.empty() ? "" : ", ") + v.name;
      throw InputError("--variants", name,
                       "unknown variant (known: " + known + "; or give a .json file)");
    }
    out.push_back(*it);
    start = comma + 1;
  }
  return out;
}

Recipe ReferenceSpec::recipe() const {
  Recipe r;
  r.file = "<reference " + text + ">";
  nlohmann::json params = nlohmann::json::object();
  if (passType != "rt_whitted") params["spp"] = spp;
  r.passes = {{.name = "reference", .type = passType, .params = params, .place = "--reference"}};
  r.outputs = {"reference.color"};
  if (passType == "rt_path") r.outputs.push_back("reference.variance");  // per-pixel variance
  return r;
}

ReferenceSpec parseReference(const std::string& text, const PassRegistry& registry) {
  ReferenceSpec spec{text, "", 1};
  const auto colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  if (kind == "whitted")
    spec.passType = "rt_whitted";
  else if (kind == "distributed")
    spec.passType = "rt_distributed";
  else if (kind == "path")
    spec.passType = "rt_path";
  else
    throw InputError("--reference", text, "expected whitted, distributed:SPP or path:SPP");
  if (colon != std::string::npos) {
    if (kind == "whitted") throw InputError("--reference", text, "whitted takes no sample count");
    try {
      std::size_t used = 0;
      spec.spp = std::stoi(text.substr(colon + 1), &used);
      if (used != text.size() - colon - 1 || spec.spp < 1) throw std::invalid_argument("spp");
    } catch (const std::exception&) {
      throw InputError("--reference", text, "SPP must be a positive whole number");
    }
  } else if (kind != "whitted") {
    spec.spp = 64;
  }
  if (!registry.find(spec.passType))
    throw InputError("--reference", text, "this build has no '" + spec.passType + "' pass");
  return spec;
}

}  // namespace diptych::cli
