#pragma once
// JSON from user files, parsed and described with bounds: nlohmann's parser is iterative, but
// dump(), copies and comparisons recurse, so a value nested 100,000 deep overflows the stack
// wherever it is later touched. We refuse such nesting while parsing (kMaxJsonDepth, far above
// any real scene, recipe or glTF) and error messages describe values without dumping them whole.
#include <nlohmann/json.hpp>
#include <string>

namespace diptych {

constexpr int kMaxJsonDepth = 256;

// Throws InputError(file, "byte N", ...) on malformed JSON or nesting deeper than kMaxJsonDepth.
nlohmann::json parseJsonText(const std::string& text, const std::string& file);

// Throws InputError naming `file` and the byte offset if `text` nests arrays/objects deeper
// than kMaxJsonDepth (strings are skipped, so brackets inside them do not count).
void checkJsonDepth(const std::string& text, const std::string& file);

// A short description of a value for error messages, never longer than about 60 characters
// and never recursive: numbers, booleans and null as written; strings quoted and truncated;
// containers by kind and size ("an array of 3 elements").
std::string describeJson(const nlohmann::json& value);

}  // namespace diptych
