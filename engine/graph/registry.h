#pragma once
// Pass types by name: each with its technique slot (if it produces one), a one-line summary,
// its parameter schema and the parameter presets `diptych compare` runs by default.
// passes/registry.cpp registers every built-in pass, one entry per type.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/graph/params.h"
#include "engine/graph/pass.h"

namespace diptych {

// A named parameter set, e.g. {"shadow-map-256-none", "resolution=256,bias=none"} (the text
// after TYPE: in --slot SLOT=TYPE:k=v,...).
struct ParamPreset {
  std::string name, params;
};

struct PassTypeInfo {
  std::string name;
  std::string slot;     // the technique slot it produces (passes/slots.h); "" for other passes
  std::string summary;  // one line for `diptych passes` and docs
  ParamSchema params;
  std::vector<ParamPreset> presets;  // compare's default variants; none: one with the defaults
  std::function<std::unique_ptr<Pass>()> create;
};

// An output renamed after recipes were written: `type.old` -> `type.renamed`. A recipe that
// reads the old spelling, or names the input of that edge by the old name, is an error that
// gives the new one.
struct RenamedOutput {
  std::string passType, old, renamed;
};

class PassRegistry {
 public:
  void add(PassTypeInfo info);
  // Fills `create` with P's constructor and `params` with P::schema(), when P declares one.
  template <class P>
  void add(PassTypeInfo info) {
    if constexpr (requires { P::schema(); }) info.params = P::schema();
    info.create = [] { return std::make_unique<P>(); };
    add(std::move(info));
  }
  const PassTypeInfo* find(const std::string& name) const;
  std::vector<std::string> names() const;  // sorted
  // In registration order.
  const std::vector<PassTypeInfo>& all() const { return types_; }
  std::vector<const PassTypeInfo*> producersOf(const std::string& slot) const;
  void addRenamedOutput(RenamedOutput r) { renamed_.push_back(std::move(r)); }
  const std::vector<RenamedOutput>& renamedOutputs() const { return renamed_; }

 private:
  std::vector<PassTypeInfo> types_;
  std::vector<RenamedOutput> renamed_;
};

}  // namespace diptych
