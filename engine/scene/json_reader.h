#pragma once
// A strict reader over nlohmann::json used by the scene JSON loader: every value is read
// through a JsonObject that knows its JSON path ("objects[2].material") for errors, and every
// key an object has but nobody read is reported as unknown (typos must not pass silently).
#include <nlohmann/json.hpp>

#include <optional>
#include <set>
#include <string>

#include "engine/core/error.h"
#include "engine/core/math.h"

namespace diptych::jsonread {

using nlohmann::json;

class JsonObject {
 public:
  // Throws unless `value` is an object.
  JsonObject(const json& value, std::string path, const std::string& file);

  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }
  std::string pathOf(const std::string& key) const;
  bool has(const std::string& key) const { return value_.contains(key); }
  // The raw value (marks the key used); nullptr when absent.
  const json* find(const std::string& key);

  std::optional<float> number(const std::string& key);
  float number(const std::string& key, float fallback) { return number(key).value_or(fallback); }
  float requiredNumber(const std::string& key);
  std::optional<int> integer(const std::string& key);
  bool boolean(const std::string& key, bool fallback);
  std::optional<std::string> string(const std::string& key);
  std::string requiredString(const std::string& key);
  std::optional<vec3> vector3(const std::string& key);
  vec3 vector3(const std::string& key, vec3 fallback) { return vector3(key).value_or(fallback); }
  vec3 requiredVector3(const std::string& key);
  std::optional<JsonObject> object(const std::string& key);

  // Throws naming the first key that was never read.
  void rejectUnknownKeys() const;
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  const json& value_;
  std::string path_;
  // A copy: callers pass temporaries (readCameraFile's path.string()), and a reference to one
  // named another string in its error messages once the temporary's stack slot was reused
  // ("camera: camera: missing" instead of "nocam.json: camera: missing", ASan build, session 29).
  std::string file_;
  std::set<std::string> used_;
};

// Value converters that name `path` on failure (used for array elements too).
float toNumber(const json& v, const std::string& path, const std::string& file);
vec3 toVector3(const json& v, const std::string& path, const std::string& file);
vec2 toVector2(const json& v, const std::string& path, const std::string& file);
std::string describeType(const json& v);

}  // namespace diptych::jsonread
