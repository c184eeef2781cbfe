#pragma once
// Sweep specifications (docs/sweep.md): `--vary KEY=LIST|START:STOP:STEP|START:STOP:logN` axes
// and their cartesian product. Pass-parameter keys are checked by compiling the recipe of every
// point (the pass's own parameter checks), before anything is rendered.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace diptych::cli {

// What an axis changes. Light and view axes change the scene state (light direction, camera,
// frame size), so each distinct state gets its own exact reference; pass axes change only the
// producer under study.
enum class AxisKind { Pass, Light, View };

// Keys of --vary-light: the swept light's direction, in degrees (directional lights).
inline const std::vector<std::string>& lightKeys() {
  static const std::vector<std::string> keys = {"elevation", "azimuth"};
  return keys;
}
// Keys of --vary-view: "size" (WIDTHxHEIGHT strings), "camera_azimuth" (degrees the camera
// orbits its target about the world y axis, from the scene's camera) and "camera_distance"
// (factor on the scene camera's distance to its target; > 0).
inline const std::vector<std::string>& viewKeys() {
  static const std::vector<std::string> keys = {"size", "camera_azimuth", "camera_distance"};
  return keys;
}
// The option that introduces an axis of that kind (for messages and the results header).
const char* axisOption(AxisKind kind);

struct SweepAxis {
  std::string key, text;  // text: as given, for errors and the results header
  AxisKind kind = AxisKind::Pass;
  std::vector<nlohmann::json> values;
};

// Throws InputError(axisOption(kind), text, ...) for a malformed or empty range, a duplicated
// value list entry, an unknown light/view key or a value of the wrong type.
SweepAxis parseAxis(const std::string& text, AxisKind kind);

// Every combination, light and view axes outermost (so points sharing a scene state are adjacent);
// each point maps key -> value. Throws InputError when a key is swept twice. At most
// kMaxSweepPoints points (InputError beyond): every point is compiled before rendering.
inline constexpr long kMaxSweepPoints = 10000;
// Largest image side a sweep renders (--size and view sizes).
inline constexpr int kMaxSweepSide = 8192;
std::vector<nlohmann::json> cartesianProduct(const std::vector<SweepAxis>& axes);

}  // namespace diptych::cli
