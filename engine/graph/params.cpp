#include "engine/graph/params.h"

#include <cmath>
#include <cstdint>

#include "engine/core/error.h"
#include "engine/core/known.h"

namespace diptych {

ParamSpec ParamSpec::number(std::string name, double fallback, double lo, double hi,
                            std::string doc) {
  return {std::move(name), Type::Number, fallback, lo, hi, {}, std::move(doc)};
}
ParamSpec ParamSpec::integer(std::string name, int fallback, int lo, int hi, std::string doc) {
  return {std::move(name), Type::Integer, fallback, double(lo), double(hi), {}, std::move(doc)};
}
ParamSpec ParamSpec::boolean(std::string name, bool fallback, std::string doc) {
  return {std::move(name), Type::Boolean, fallback, 0, 0, {}, std::move(doc)};
}
ParamSpec ParamSpec::choice(std::string name, std::string fallback,
                            std::vector<std::string> choices, std::string doc) {
  return {std::move(name),    Type::Choice,  std::move(fallback), 0, 0,
          std::move(choices), std::move(doc)};
}

std::string ParamSpec::describe() const {
  switch (type) {
    case Type::Number:
      return "number in [" + nlohmann::json(lo).dump() + ", " + nlohmann::json(hi).dump() +
             "], default " + fallback.dump();
    case Type::Integer:
      return "integer in [" + std::to_string(std::int64_t(lo)) + ", " +
             std::to_string(std::int64_t(hi)) + "], default " + fallback.dump();
    case Type::Boolean:
      return "true or false, default " + fallback.dump();
    case Type::Choice:
      return "one of " + joinNames(choices) + "; default " + fallback.get<std::string>();
  }
  return "?";
}

PassParams::PassParams(nlohmann::json values, const ParamSchema& schema, std::string passType,
                       std::string file, std::string place)
    : values_(std::move(values)),
      schema_(&schema),
      passType_(std::move(passType)),
      file_(std::move(file)),
      place_(std::move(place)) {
  if (values_.is_null()) values_ = nlohmann::json::object();
  if (!values_.is_object()) throw InputError(file_, place_, "parameters must be a JSON object");
  for (const auto& [key, value] : values_.items()) {
    const ParamSpec* spec = nullptr;
    for (const ParamSpec& s : schema)
      if (s.name == key) spec = &s;
    if (!spec) {
      std::vector<std::string> known;
      for (const ParamSpec& s : schema) known.push_back(s.name);
      fail(key, "unknown parameter for pass type '" + passType_ + "' (" +
                    (known.empty() ? "it has none" : "known: " + joinNames(known)) + ")");
    }
    check(*spec, value);
  }
}

void PassParams::fail(const std::string& key, const std::string& message) const {
  throw InputError(file_, place_ + "." + key, message);
}

void PassParams::check(const ParamSpec& spec, const nlohmann::json& v) const {
  const std::string& key = spec.name;
  switch (spec.type) {
    case ParamSpec::Type::Number:
    case ParamSpec::Type::Integer: {
      if (!v.is_number()) fail(key, "expected a number, got " + v.dump());
      const double d = v.get<double>();
      if (!std::isfinite(d) || d < spec.lo || d > spec.hi)
        fail(key, "value " + v.dump() + " is outside [" + nlohmann::json(spec.lo).dump() + ", " +
                      nlohmann::json(spec.hi).dump() + "]");
      if (spec.type == ParamSpec::Type::Integer && d != std::floor(d))
        fail(key, "expected a whole number, got " + v.dump());
      return;
    }
    case ParamSpec::Type::Boolean:
      if (!v.is_boolean()) fail(key, "expected true or false");
      return;
    case ParamSpec::Type::Choice: {
      if (!v.is_string()) fail(key, "expected a string");
      const std::string s = v.get<std::string>();
      for (const std::string& c : spec.choices)
        if (c == s) return;
      fail(key, unknownName(key + " mode", s, spec.choices));
    }
  }
}

const nlohmann::json& PassParams::valueOrDefault(const std::string& key,
                                                 ParamSpec::Type type) const {
  if (schema_)
    for (const ParamSpec& s : *schema_) {
      if (s.name != key || s.type != type) continue;
      read_.insert(key);
      return values_.contains(key) ? values_.at(key) : s.fallback;
    }
  throw Error("pass type '" + passType_ + "' reads parameter '" + key +
              "', which its schema does not declare with that type (passes/registry.cpp)");
}

double PassParams::number(const std::string& key) const {
  return valueOrDefault(key, ParamSpec::Type::Number).get<double>();
}
int PassParams::integer(const std::string& key) const {
  return int(valueOrDefault(key, ParamSpec::Type::Integer).get<double>());
}
bool PassParams::boolean(const std::string& key) const {
  return valueOrDefault(key, ParamSpec::Type::Boolean).get<bool>();
}
std::string PassParams::string(const std::string& key) const {
  return valueOrDefault(key, ParamSpec::Type::Choice).get<std::string>();
}

void PassParams::checkAllRead() const {
  if (!schema_) return;
  for (const ParamSpec& s : *schema_)
    if (!read_.count(s.name))
      throw Error("pass type '" + passType_ + "' declares parameter '" + s.name +
                  "' but its setup never reads it (passes/registry.cpp)");
}

}  // namespace diptych
