#pragma once
// Sweep specifications (docs/sweep.md): `--vary KEY=LIST|START:STOP:STEP|START:STOP:logN` axes
// and their cartesian product. Pass-parameter keys are checked by compiling the recipe of every
// point (the pass's own parameter checks), before anything is rendered.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace diptych::cli {

// Keys of --vary-light: the swept light's direction, in degrees (directional lights).
inline const std::vector<std::string>& lightKeys() {
  static const std::vector<std::string> keys = {"elevation", "azimuth"};
  return keys;
}

struct SweepAxis {
  std::string key, text;  // text: as given, for errors and the results header
  bool light = false;     // a --vary-light axis (changes the scene state, hence the reference)
  std::vector<nlohmann::json> values;
};

// Throws InputError("--vary" / "--vary-light", text, ...) for a malformed or empty range, a
// duplicated value list entry or an unknown light key.
SweepAxis parseAxis(const std::string& text, bool light);

// Every combination, light axes outermost (so points sharing a scene state are adjacent); each
// point maps key -> value. Throws InputError when a key is swept twice.
// At most kMaxSweepPoints points (InputError beyond): every point is compiled before rendering.
inline constexpr long kMaxSweepPoints = 10000;
std::vector<nlohmann::json> cartesianProduct(const std::vector<SweepAxis>& axes);

}  // namespace diptych::cli
