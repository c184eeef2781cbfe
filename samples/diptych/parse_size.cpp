#include "samples/diptych/parse_size.h"

#include <cctype>
#include <charconv>

#include "engine/core/error.h"

namespace diptych::cli {

// Digits only, checked for overflow (sscanf's %d wraps 4294967360 to 64).
std::pair<int, int> parseSize(const std::string& text, int maxSide) {
  int w = 0, h = 0;
  const char* end = text.data() + text.size();
  const auto [afterW, errW] = std::from_chars(text.data(), end, w);
  const bool separator = afterW != end && (*afterW == 'x' || *afterW == 'X');
  const auto [afterH, errH] =
      separator ? std::from_chars(afterW + 1, end, h) : std::from_chars_result{end, std::errc()};
  const bool digits = !text.empty() && std::isdigit(static_cast<unsigned char>(text[0])) &&
                      separator && afterW + 1 != end &&
                      std::isdigit(static_cast<unsigned char>(afterW[1]));
  if (!digits || errW != std::errc() || errH != std::errc() || afterH != end || w <= 0 || h <= 0 ||
      w > maxSide || h > maxSide)
    throw InputError("--size", "",
                     "expected WIDTHxHEIGHT with each in 1.." + std::to_string(maxSide) +
                         ", got '" + text + "'");
  return {w, h};
}

}  // namespace diptych::cli
