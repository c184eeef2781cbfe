#include "samples/diptych/shading_option.h"

#include <CLI/CLI.hpp>

#include "engine/core/error.h"
#include "engine/scene/gltf_pbr.h"

namespace diptych::cli {

void addShadingOption(CLI::App* cmd, std::string& value) {
  cmd->add_option("--shading", value,
                  "Shade every material with one model: lecture or gltf (default: each "
                  "material's own, glTF materials gltf, JSON materials lecture)");
}

void checkShadingOption(const std::string& value) {
  if (!value.empty() && !parseShadingModel(value))
    throw InputError("--shading", "", "expected lecture or gltf, got '" + value + "'");
}

void applyShadingOption(Scene& scene, const std::string& value) {
  checkShadingOption(value);
  if (const auto model = value.empty() ? std::nullopt : parseShadingModel(value))
    forceShadingModel(scene, *model);
}

}  // namespace diptych::cli
