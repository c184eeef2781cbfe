#include "engine/graph/params.h"

#include <cmath>

#include "engine/core/error.h"
#include "engine/core/json_text.h"

namespace diptych {

PassParams::PassParams(nlohmann::json values, std::string file, std::string place)
    : values_(std::move(values)), file_(std::move(file)), place_(std::move(place)) {
  if (values_.is_null()) values_ = nlohmann::json::object();
  if (!values_.is_object()) throw InputError(file_, place_, "parameters must be a JSON object");
}

void PassParams::fail(const std::string& key, const std::string& message) const {
  throw InputError(file_, place_ + "." + key, message);
}

double PassParams::number(const std::string& key, double fallback, double lo, double hi) const {
  read_.insert(key);
  if (!values_.contains(key)) return fallback;
  const auto& v = values_.at(key);
  if (!v.is_number()) fail(key, "expected a number, got " + describeJson(v));
  const double d = v.get<double>();
  if (!std::isfinite(d) || d < lo || d > hi)
    fail(key, "value " + describeJson(v) + " is outside [" + nlohmann::json(lo).dump() + ", " +
                  nlohmann::json(hi).dump() + "]");
  return d;
}

int PassParams::integer(const std::string& key, int fallback, int lo, int hi) const {
  const double d = number(key, fallback, lo, hi);
  if (d != std::floor(d))
    fail(key, "expected a whole number, got " + describeJson(values_.at(key)));
  return int(d);
}

bool PassParams::boolean(const std::string& key, bool fallback) const {
  read_.insert(key);
  if (!values_.contains(key)) return fallback;
  if (!values_.at(key).is_boolean()) fail(key, "expected true or false");
  return values_.at(key).get<bool>();
}

std::string PassParams::string(const std::string& key, const std::string& fallback) const {
  read_.insert(key);
  if (!values_.contains(key)) return fallback;
  if (!values_.at(key).is_string()) fail(key, "expected a string");
  return values_.at(key).get<std::string>();
}

void PassParams::rejectUnread(const std::string& passType) const {
  for (const auto& [key, value] : values_.items())
    if (!read_.count(key)) fail(key, "unknown parameter for pass type '" + passType + "'");
}

}  // namespace diptych
