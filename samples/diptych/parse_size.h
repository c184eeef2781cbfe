#pragma once
// --size WIDTHxHEIGHT for the commands that render.
#include <string>
#include <utility>

namespace diptych::cli {

// Throws InputError("--size", ...) unless `text` is digits 'x' digits, each in 1..maxSide.
std::pair<int, int> parseSize(const std::string& text, int maxSide);

}  // namespace diptych::cli
