#pragma once
// The one way an error message lists what would have been accepted: "a, b, c".
#include <string>
#include <vector>

namespace diptych {

std::string joinNames(const std::vector<std::string>& names);
// "unknown WHAT 'VALUE' (known: a, b, c)"
std::string unknownName(const std::string& what, const std::string& value,
                        const std::vector<std::string>& known);

}  // namespace diptych
