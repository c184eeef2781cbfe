#include "engine/core/json_text.h"

#include "engine/core/error.h"

namespace diptych {

void checkJsonDepth(const std::string& text, const std::string& file) {
  int depth = 0;
  bool inString = false, escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        throw InputError(file, "byte " + std::to_string(i),
                         "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    } else if (c == ']' || c == '}') {
      --depth;  // unbalanced text is the parser's to report
    }
  }
}

nlohmann::json parseJsonText(const std::string& text, const std::string& file) {
  checkJsonDepth(text, file);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // Syntax errors carry line and column.
    throw InputError(file, "byte " + std::to_string(e.byte),
                     std::string("malformed JSON: ") + e.what());
  } catch (const nlohmann::json::exception& e) {
    // A number literal that overflows a double (1e999) is rejected here ("number overflow",
    // out_of_range), before any path is known.
    throw InputError(file, "", std::string("malformed JSON: ") + e.what());
  }
}

std::string describeJson(const nlohmann::json& value) {
  constexpr std::size_t kMaxString = 40;
  switch (value.type()) {
    case nlohmann::json::value_t::array:
      return "an array of " + std::to_string(value.size()) + " elements";
    case nlohmann::json::value_t::object:
      return "an object of " + std::to_string(value.size()) + " keys";
    case nlohmann::json::value_t::string: {
      // Cutting may split a UTF-8 sequence: dump() replaces it rather than throwing.
      const std::string& s = value.get_ref<const std::string&>();
      const std::string quoted =
          nlohmann::json(s.substr(0, kMaxString))
              .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
      if (s.size() <= kMaxString) return quoted;
      return quoted + "... (" + std::to_string(s.size()) + " bytes)";
    }
    case nlohmann::json::value_t::binary:
      return "binary data";
    default:
      return value.dump();  // a scalar: number, boolean, null or discarded
  }
}

}  // namespace diptych
