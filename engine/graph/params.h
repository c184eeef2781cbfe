#pragma once
// Parameters of one pass, from a recipe or the command line. Getters check types and ranges
// and name the place ("recipe.json: passes[2].params.size") on error. Every key must be read by
// the pass's setup: leftovers are reported as unknown parameters, so typos never pass silently.
#include <nlohmann/json.hpp>
#include <set>
#include <string>

namespace diptych {

class PassParams {
 public:
  PassParams() = default;
  PassParams(nlohmann::json values, std::string file, std::string place);

  double number(const std::string& key, double fallback, double lo, double hi) const;
  int integer(const std::string& key, int fallback, int lo, int hi) const;
  bool boolean(const std::string& key, bool fallback) const;
  std::string string(const std::string& key, const std::string& fallback) const;
  bool has(const std::string& key) const { return values_.contains(key); }

  // Throws InputError for the first key no getter asked for.
  void rejectUnread(const std::string& passType) const;
  const nlohmann::json& values() const { return values_; }
  // Throws InputError at this key's recipe place, for checks across parameters.
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  nlohmann::json values_ = nlohmann::json::object();
  std::string file_, place_;
  mutable std::set<std::string> read_;
};

}  // namespace diptych
