#include "engine/core/known.h"

namespace diptych {

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string unknownName(const std::string& what, const std::string& value,
                        const std::vector<std::string>& known) {
  return "unknown " + what + " '" + value + "' (known: " + joinNames(known) + ")";
}

}  // namespace diptych
