#pragma once
// Parameters of one pass. Each pass type declares its parameters once, as a schema (name, type,
// range or choices, default, doc line) in its registration (passes/registry.cpp); recipe and
// command-line values are checked against it before setup runs, and `diptych passes` and the
// docs print it. Errors name the place ("recipe.json: passes[2].params.size").
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace diptych {

struct ParamSpec {
  enum class Type { Number, Integer, Boolean, Choice };
  std::string name;
  Type type = Type::Number;
  nlohmann::json fallback;           // the default
  double lo = 0, hi = 0;             // Number, Integer: the closed range
  std::vector<std::string> choices;  // Choice: the accepted strings
  std::string doc;                   // one line

  static ParamSpec number(std::string name, double fallback, double lo, double hi, std::string doc);
  static ParamSpec integer(std::string name, int fallback, int lo, int hi, std::string doc);
  static ParamSpec boolean(std::string name, bool fallback, std::string doc);
  static ParamSpec choice(std::string name, std::string fallback, std::vector<std::string> choices,
                          std::string doc);
  // "integer in [1, 4096], default 16" (for --help and docs)
  std::string describe() const;
};
using ParamSchema = std::vector<ParamSpec>;

class PassParams {
 public:
  PassParams() = default;
  // Checks every key of `values` against `schema` (declared, type, range, choices); throws
  // InputError at the key's place. `schema` must outlive this object.
  PassParams(nlohmann::json values, const ParamSchema& schema, std::string passType,
             std::string file, std::string place);

  // The value or the schema's default. Reading a key the schema does not declare with that
  // type is a registration bug (Error).
  double number(const std::string& key) const;
  int integer(const std::string& key) const;
  bool boolean(const std::string& key) const;
  std::string string(const std::string& key) const;  // a Choice
  bool has(const std::string& key) const { return values_.contains(key); }

  // Throws Error for a declared parameter setup never read: the schema must describe the code.
  void checkAllRead() const;
  const nlohmann::json& values() const { return values_; }
  // Throws InputError at this key's recipe place, for checks across parameters.
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  const nlohmann::json& valueOrDefault(const std::string& key, ParamSpec::Type type) const;
  void check(const ParamSpec& spec, const nlohmann::json& value) const;

  nlohmann::json values_ = nlohmann::json::object();
  const ParamSchema* schema_ = nullptr;
  std::string passType_, file_, place_;
  mutable std::set<std::string> read_;
};

}  // namespace diptych
