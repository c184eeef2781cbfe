#pragma once
// --shading lecture|gltf for the commands that render (render, compare, sweep): every material
// shaded by one model (docs/materials.md, "Two shading models").
#include <string>

#include "engine/scene/scene.h"

namespace CLI {
class App;
}

namespace diptych::cli {

void addShadingOption(CLI::App* cmd, std::string& value);

// Throws InputError("--shading", ...) unless `value` is empty, "lecture" or "gltf".
void checkShadingOption(const std::string& value);

// Applies a non-empty --shading to every material of the scene (after checkShadingOption).
void applyShadingOption(Scene& scene, const std::string& value);

}  // namespace diptych::cli
