#pragma once
// `diptych view --script FILE`: commands run one per rendered frame, for tests and recorded
// demonstrations (docs/viewer.md, "Script"). The whole file is parsed and checked before the
// window opens; an error names the file and line.
#include <string>
#include <vector>

namespace diptych::view {

struct ScriptCommand {
  int line = 0;
  std::string verb;               // slot, param, camera, split, overlay, reference-samples,
                                  // exposure, resize, frames, screenshot, write-recipe,
                                  // motion, quit
  std::vector<std::string> args;  // the words after the verb
  std::vector<double> numbers;    // numeric arguments where the verb takes numbers
};

std::vector<ScriptCommand> loadScript(const std::string& path);

}  // namespace diptych::view
