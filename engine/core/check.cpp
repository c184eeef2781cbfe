#include "engine/core/check.h"

#include <string_view>

namespace diptych {
namespace {

// __FILE__ is absolute or relative to the build folder (ccache's base-dir rewrite); keep the
// part from the top-level source folder on, the same for every checkout.
std::string_view sourcePath(std::string_view file) {
  std::size_t best = std::string_view::npos;
  for (std::string_view top : {"engine/", "passes/", "samples/", "tests/"}) {
    for (std::size_t at = file.find(top); at != std::string_view::npos;
         at = file.find(top, at + 1)) {
      if ((at == 0 || file[at - 1] == '/') && (best == std::string_view::npos || at > best))
        best = at;
    }
  }
  return best == std::string_view::npos ? file : file.substr(best);
}

}  // namespace

void failCheck(const char* file, int line, const char* expression, const std::string& message) {
  throw InternalError("internal error: " + std::string(sourcePath(file)) + ":" +
                      std::to_string(line) + ": check '" + expression + "' failed: " + message);
}

}  // namespace diptych
