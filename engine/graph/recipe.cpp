#include "engine/graph/recipe.h"

#include <set>

#include "engine/core/error.h"
#include "engine/core/input_file.h"
#include "engine/core/json_text.h"

namespace diptych {
namespace {

void rejectUnknownKeys(const nlohmann::json& obj, const std::set<std::string>& known,
                       const std::string& file, const std::string& place) {
  for (const auto& [key, value] : obj.items())
    if (!known.count(key)) throw InputError(file, place + "." + key, "unknown key");
}

std::string requireString(const nlohmann::json& obj, const std::string& key,
                          const std::string& file, const std::string& place) {
  if (!obj.contains(key)) throw InputError(file, place, "missing \"" + key + "\"");
  if (!obj.at(key).is_string() || obj.at(key).get<std::string>().empty())
    throw InputError(file, place + "." + key, "expected a non-empty string");
  return obj.at(key).get<std::string>();
}

}  // namespace

std::pair<std::string, std::string> splitResourceName(const std::string& name,
                                                      const std::string& file,
                                                      const std::string& place) {
  const auto dot = name.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == name.size())
    throw InputError(file, place, "'" + name + "' is not of the form \"pass.output\"");
  return {name.substr(0, dot), name.substr(dot + 1)};
}

Recipe parseRecipe(const nlohmann::json& json, const std::string& file) {
  Recipe recipe;
  recipe.file = file;
  if (!json.is_object()) throw InputError(file, "", "a recipe must be a JSON object");
  rejectUnknownKeys(json, {"passes", "outputs", "description"}, file, "");
  if (!json.contains("passes") || !json.at("passes").is_array() || json.at("passes").empty())
    throw InputError(file, "passes", "expected a non-empty array of passes");
  std::set<std::string> names;
  for (std::size_t i = 0; i < json.at("passes").size(); ++i) {
    const auto& p = json.at("passes")[i];
    const std::string place = "passes[" + std::to_string(i) + "]";
    if (!p.is_object()) throw InputError(file, place, "expected an object");
    rejectUnknownKeys(p, {"name", "type", "params", "inputs"}, file, place);
    RecipePass pass;
    pass.place = place;
    pass.type = requireString(p, "type", file, place);
    pass.name = p.contains("name") ? requireString(p, "name", file, place) : pass.type;
    if (pass.name.find('.') != std::string::npos)
      throw InputError(file, place + ".name", "a pass name may not contain '.'");
    if (!names.insert(pass.name).second)
      throw InputError(file, place + ".name", "duplicate pass name '" + pass.name + "'");
    if (p.contains("params")) {
      if (!p.at("params").is_object())
        throw InputError(file, place + ".params", "expected an object");
      pass.params = p.at("params");
    }
    if (p.contains("inputs")) {
      if (!p.at("inputs").is_object())
        throw InputError(file, place + ".inputs", "expected an object");
      for (const auto& [slot, source] : p.at("inputs").items()) {
        if (!source.is_string())
          throw InputError(file, place + ".inputs." + slot, "expected \"pass.output\"");
        splitResourceName(source.get<std::string>(), file, place + ".inputs." + slot);
        pass.inputs[slot] = source.get<std::string>();
      }
    }
    recipe.passes.push_back(std::move(pass));
  }
  if (!json.contains("outputs") || !json.at("outputs").is_array() || json.at("outputs").empty())
    throw InputError(file, "outputs", "expected a non-empty array of \"pass.output\" names");
  for (std::size_t i = 0; i < json.at("outputs").size(); ++i) {
    const auto& o = json.at("outputs")[i];
    const std::string place = "outputs[" + std::to_string(i) + "]";
    if (!o.is_string()) throw InputError(file, place, "expected \"pass.output\"");
    splitResourceName(o.get<std::string>(), file, place);
    recipe.outputs.push_back(o.get<std::string>());
  }
  return recipe;
}

Recipe loadRecipe(const std::filesystem::path& path) {
  const std::string text = readInputFile(path, kMaxJsonFileBytes);
  return parseRecipe(parseJsonText(text, path.string()), path.string());
}

}  // namespace diptych
