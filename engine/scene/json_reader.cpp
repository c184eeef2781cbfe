#include "engine/scene/json_reader.h"

#include <cmath>

#include "engine/core/json_text.h"

namespace diptych::jsonread {

std::string describeType(const json& v) {
  return v.type_name();
}

float toNumber(const json& v, const std::string& path, const std::string& file) {
  if (!v.is_number()) throw InputError(file, path, "expected a number, found " + describeType(v));
  // nlohmann parses an overflowing literal such as 1e999 to +inf; a double that does not fit a
  // float is just as unusable.
  const double d = v.get<double>();
  const float f = float(d);
  if (!std::isfinite(d) || !std::isfinite(f))
    throw InputError(file, path, "non-finite number (" + describeJson(v) + ")");
  return f;
}

namespace {
template <int N>
glm::vec<N, float> toVector(const json& v, const std::string& path, const std::string& file) {
  if (!v.is_array() || v.size() != N)
    throw InputError(
        file, path,
        "expected an array of " + std::to_string(N) + " numbers, found " +
            (v.is_array() ? "an array of " + std::to_string(v.size()) : describeType(v)));
  glm::vec<N, float> out;
  for (int i = 0; i < N; ++i) out[i] = toNumber(v[i], path + "[" + std::to_string(i) + "]", file);
  return out;
}
}  // namespace

vec3 toVector3(const json& v, const std::string& path, const std::string& file) {
  return toVector<3>(v, path, file);
}
vec2 toVector2(const json& v, const std::string& path, const std::string& file) {
  return toVector<2>(v, path, file);
}

JsonObject::JsonObject(const json& value, std::string path, const std::string& file)
    : value_(value), path_(std::move(path)), file_(file) {
  if (!value_.is_object())
    throw InputError(file_, path_.empty() ? "(top level)" : path_,
                     "expected an object, found " + describeType(value_));
}

std::string JsonObject::pathOf(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

const json* JsonObject::find(const std::string& key) {
  auto it = value_.find(key);
  if (it == value_.end()) return nullptr;
  used_.insert(key);
  return &*it;
}

void JsonObject::fail(const std::string& key, const std::string& message) const {
  throw InputError(file_, key.empty() ? path_ : pathOf(key), message);
}

std::optional<float> JsonObject::number(const std::string& key) {
  const json* v = find(key);
  if (!v) return std::nullopt;
  return toNumber(*v, pathOf(key), file_);
}

float JsonObject::requiredNumber(const std::string& key) {
  auto v = number(key);
  if (!v) fail(key, "required number is missing");
  return *v;
}

std::optional<int> JsonObject::integer(const std::string& key) {
  const json* v = find(key);
  if (!v) return std::nullopt;
  if (!v->is_number_integer()) fail(key, "expected an integer, found " + describeJson(*v));
  const long long i = v->get<long long>();
  if (i < -(1ll << 30) || i > (1ll << 30)) fail(key, "integer out of range");
  return int(i);
}

bool JsonObject::boolean(const std::string& key, bool fallback) {
  const json* v = find(key);
  if (!v) return fallback;
  if (!v->is_boolean()) fail(key, "expected true or false, found " + describeType(*v));
  return v->get<bool>();
}

std::optional<std::string> JsonObject::string(const std::string& key) {
  const json* v = find(key);
  if (!v) return std::nullopt;
  if (!v->is_string()) fail(key, "expected a string, found " + describeType(*v));
  return v->get<std::string>();
}

std::string JsonObject::requiredString(const std::string& key) {
  auto v = string(key);
  if (!v) fail(key, "required string is missing");
  return *v;
}

std::optional<vec3> JsonObject::vector3(const std::string& key) {
  const json* v = find(key);
  if (!v) return std::nullopt;
  return toVector3(*v, pathOf(key), file_);
}

vec3 JsonObject::requiredVector3(const std::string& key) {
  auto v = vector3(key);
  if (!v) fail(key, "required [x, y, z] is missing");
  return *v;
}

std::optional<JsonObject> JsonObject::object(const std::string& key) {
  const json* v = find(key);
  if (!v) return std::nullopt;
  return JsonObject(*v, pathOf(key), file_);
}

void JsonObject::rejectUnknownKeys() const {
  for (auto it = value_.begin(); it != value_.end(); ++it)
    if (!used_.count(it.key())) fail(it.key(), "unknown key '" + it.key() + "'");
}

}  // namespace diptych::jsonread
