#include "samples/diptych/view/script.h"

#include <cmath>
#include <map>
#include <sstream>

#include "engine/core/error.h"
#include "engine/core/input_file.h"
#include "passes/slots.h"

namespace diptych::view {
namespace {

double number(const std::string& path, int line, const std::string& word) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(word, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != word.size() || !std::isfinite(v))
    throw InputError(path, "line " + std::to_string(line), "expected a number, got '" + word + "'");
  return v;
}

// verb -> {min words, max words, first numeric word (-1: none)}
struct Arity {
  std::size_t min, max;
  int firstNumber;
};
const std::map<std::string, Arity>& verbs() {
  static const std::map<std::string, Arity> v = {
      {"slot", {1, 1, -1}},         {"param", {2, 2, -1}},   {"camera", {1, 4, 1}},
      {"split", {1, 2, 1}},         {"overlay", {1, 1, -1}}, {"exposure", {1, 1, 0}},
      {"resize", {2, 2, 0}},        {"frames", {1, 1, 0}},   {"screenshot", {1, 1, -1}},
      {"write-recipe", {1, 1, -1}}, {"motion", {1, 2, 1}},   {"time", {1, 1, 0}},
      {"quit", {0, 0, -1}}};
  return v;
}

}  // namespace

std::vector<ScriptCommand> loadScript(const std::string& path) {
  std::istringstream in(readInputFile(path, 1 << 20));
  std::vector<ScriptCommand> out;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    if (auto hash = text.find('#'); hash != std::string::npos) text.resize(hash);
    std::istringstream words(text);
    ScriptCommand c{.line = line};
    if (!(words >> c.verb)) continue;
    for (std::string w; words >> w;) c.args.push_back(w);
    const std::string place = "line " + std::to_string(line);
    auto it = verbs().find(c.verb);
    if (it == verbs().end())
      throw InputError(path, place,
                       "unknown command '" + c.verb +
                           "' (slot, param, camera, split, overlay, exposure, resize, frames, "
                           "screenshot, write-recipe, motion, time, quit)");
    if (c.args.size() < it->second.min || c.args.size() > it->second.max)
      throw InputError(path, place,
                       "'" + c.verb + "' takes " + std::to_string(it->second.min) + ".." +
                           std::to_string(it->second.max) + " words");
    const bool cameraFile = c.verb == "camera" && (c.args[0] == "save" || c.args[0] == "load");
    if (it->second.firstNumber >= 0 && !cameraFile)
      for (std::size_t i = std::size_t(it->second.firstNumber); i < c.args.size(); ++i)
        c.numbers.push_back(number(path, line, c.args[i]));
    if (c.verb == "slot") parseSlotOverride(c.args[0]);  // fails here, naming the text
    if (c.verb == "camera") {
      static const std::map<std::string, std::size_t> motions = {
          {"orbit", 2}, {"pan", 2}, {"dolly", 1}, {"fly", 3}, {"reset", 0}};
      const bool file = cameraFile;
      auto m = motions.find(c.args[0]);
      if (file ? c.args.size() != 2 : (m == motions.end() || c.numbers.size() != m->second))
        throw InputError(path, place,
                         "expected 'camera orbit YAW PITCH' (degrees), 'camera pan DX DY', "
                         "'camera dolly FACTOR', 'camera fly RIGHT UP FORWARD', 'camera reset', "
                         "'camera save FILE' or 'camera load FILE'");
    }
    if (c.verb == "overlay" && c.args[0] != "none" && c.args[0] != "flip" && c.args[0] != "abs")
      throw InputError(path, place, "overlay is none, flip or abs");
    if (c.verb == "split" && c.args[0] != "on" && c.args[0] != "off")
      throw InputError(path, place, "expected 'split on [POSITION in 0..1]' or 'split off'");
    if (c.verb == "motion" && (c.args[0] == "on") != (c.numbers.size() == 1))
      throw InputError(path, place, "expected 'motion on FACTOR' or 'motion off'");
    if (c.verb == "param" && c.args[1].find('=') == std::string::npos)
      throw InputError(path, place, "expected 'param SLOT KEY=VALUE'");
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace diptych::view
