#include "samples/diptych/compare/variants.h"

#include <algorithm>
#include <fstream>
#include <set>
#include <tuple>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/input_file.h"
#include "engine/core/json_text.h"
#include "engine/core/known.h"
#include "engine/scene/primitives.h"
#include "engine/shading/surface_detail.h"
#include "passes/registry.h"
#include "passes/slots.h"

namespace diptych::cli {

namespace {
void setTextureSamples(Recipe& recipe, int textureSamples) {
  for (RecipePass& pass : recipe.passes) {
    if (pass.type == "texture_supersample") pass.params["samples"] = textureSamples;
    // The exact producers of textures seen in a mirror or through glass (rt_secondary.h).
    if (pass.type == "rt_reflection" || pass.type == "rt_transmission")
      pass.params["texture_samples"] = textureSamples;
  }
}
}  // namespace

Recipe exactHybridRecipe(int textureSamples) {
  Recipe recipe = defaultHybridRecipe();
  setTextureSamples(recipe, textureSamples);
  return recipe;
}

Recipe Variant::build(const PassRegistry& registry, int exactTextureSamples) const {
  Recipe recipe = recipeFile.empty() ? defaultHybridRecipe() : loadRecipe(recipeFile);
  if (exactTextureSamples > 0) setTextureSamples(recipe, exactTextureSamples);
  for (const std::string& s : slots) applySlotOverride(recipe, parseSlotOverride(s), registry);
  return recipe;
}

std::vector<Variant> defaultVariants(const PassRegistry& registry) {
  // From the registry: every non-exact producer of every slot, each swapped alone into the
  // all-exact hybrid so that its error is that of one term (one variant per parameter preset,
  // or one with the defaults, named after the type); plus an all-raster frame made of each
  // slot's raster approximation (passes/slots.cpp).
  std::vector<Variant> out = {{"hybrid-exact", "", {}}, {"raster", "", {}}};
  for (const TechniqueSlot& slot : techniqueSlots()) {
    out[1].slots.push_back(slot.name + "=" + slot.raster);
    for (const PassTypeInfo* type : registry.producersOf(slot.name)) {
      if (type->name == slot.exact) continue;
      const std::string swap = slot.name + "=" + type->name;
      if (type->presets.empty()) {
        std::string name = type->name;
        std::replace(name.begin(), name.end(), '_', '-');
        out.push_back({name, "", {swap}});
      }
      for (const ParamPreset& p : type->presets)
        out.push_back({p.name, "", {swap + ":" + p.params}});
    }
  }
  return out;
}

std::vector<Variant> geometryVariants() {
  std::vector<Variant> out;
  for (int segments : {16, 64, 256})
    out.push_back({"geometry-" + std::to_string(segments), "", {}, segments});
  return out;
}

std::vector<Variant> textureLodVariants(bool reflective, bool transmissive) {
  std::vector<Variant> out;
  for (const auto& [slot, kind, wanted] :
       {std::tuple{"reflection", "rt_reflection", reflective},
        std::tuple{"transmission", "rt_transmission", transmissive}}) {
    if (!wanted) continue;
    const std::string swap = std::string(slot) + "=" + kind;
    out.push_back({std::string(slot) + "-level0", "", {swap}});
    out.push_back({std::string(slot) + "-cone", "", {swap + ":texture_lod=cone"}});
  }
  return out;
}

std::vector<Variant> surfaceDetailVariants() {
  std::vector<Variant> out;
  for (const char* mode : {"flat", "bump", "normal_map", "displaced"}) {
    std::string name = std::string("detail-") + mode;
    std::replace(name.begin(), name.end(), '_', '-');
    out.push_back({name, "", {}, 0, mode});
  }
  return out;
}

std::vector<Variant> motionVariants(const PassRegistry& registry) {
  constexpr int kInstants = 8;
  const std::vector<Variant> defaults = defaultVariants(registry);  // hybrid-exact, raster first
  std::vector<Variant> out;
  for (const char* base : {"raster", "hybrid-exact"}) {
    Variant v = *std::find_if(defaults.begin(), defaults.end(),
                              [&](const Variant& d) { return d.name == base; });
    v.name = std::string(base == std::string("raster") ? "raster" : "hybrid") + "-accumulation-" +
             std::to_string(kInstants);
    v.shutterSamples = kInstants;
    out.push_back(std::move(v));
  }
  return out;
}

namespace {
bool changesDetail(const Scene& scene, const Variant& variant) {
  const auto detail = parseSurfaceDetail(variant.surfaceDetail);
  return detail && *detail != SurfaceDetail::Bump && hasBumpMaps(scene);
}
}  // namespace

nlohmann::json variantSceneState(const Scene& scene, const Variant& variant) {
  return {{"tessellation", std::max(variant.tessellation, 0)},
          {"surface_detail",
           changesDetail(scene, variant) ? variant.surfaceDetail : std::string("as authored")},
          {"shutter_samples", std::max(variant.shutterSamples, 0)}};
}

std::optional<Scene> variantScene(const Scene& scene, const Variant& variant) {
  const auto detail = parseSurfaceDetail(variant.surfaceDetail);
  if (variant.tessellation <= 0 && !changesDetail(scene, variant)) return std::nullopt;
  Scene out = variant.tessellation > 0 ? tessellateAnalytic(scene, variant.tessellation) : scene;
  if (changesDetail(scene, variant)) out = withSurfaceDetail(out, *detail);
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
        if (key != "name" && key != "recipe" && key != "slots" && key != "tessellation" &&
            key != "surface_detail" && key != "shutter_samples")
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
      if (v.contains("tessellation")) {
        const auto& t = v["tessellation"];
        if (!t.is_number_integer() || t.get<long long>() < 3 || t.get<long long>() > 4096)
          throw InputError(spec, place + ".tessellation", "expected an integer in 3..4096");
        variant.tessellation = t.get<int>();
      }
      if (v.contains("surface_detail")) {
        const auto& d = v["surface_detail"];
        if (!d.is_string() || !parseSurfaceDetail(d.get<std::string>()))
          throw InputError(spec, place + ".surface_detail",
                           "expected \"flat\", \"bump\", \"normal_map\" or \"displaced\"");
        variant.surfaceDetail = d.get<std::string>();
      }
      if (v.contains("shutter_samples")) {
        const auto& n = v["shutter_samples"];
        if (!n.is_number_integer() || n.get<long long>() < 2 || n.get<long long>() > 256)
          throw InputError(spec, place + ".shutter_samples", "expected an integer in 2..256");
        variant.shutterSamples = n.get<int>();
      }
      out.push_back(variant);
    }
    return out;
  }
  std::vector<Variant> all = defaultVariants(registry);
  for (const Variant& v : geometryVariants()) all.push_back(v);
  for (const Variant& v : surfaceDetailVariants()) all.push_back(v);
  for (const Variant& v : textureLodVariants(true, true)) all.push_back(v);
  for (const Variant& v : motionVariants(registry)) all.push_back(v);
  std::vector<Variant> out;
  std::size_t start = 0;
  while (start <= spec.size()) {
    const std::size_t comma = std::min(spec.find(',', start), spec.size());
    const std::string name = spec.substr(start, comma - start);
    auto it =
        std::find_if(all.begin(), all.end(), [&](const Variant& v) { return v.name == name; });
    if (it == all.end()) {
      std::vector<std::string> known;
      for (const Variant& v : all) known.push_back(v.name);
      throw InputError("--variants", name,
                       unknownName("variant", name, known) + "; or give a .json file");
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
  if (passType == "rt_whitted" && textureSamples > 1) params["texture_samples"] = textureSamples;
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
