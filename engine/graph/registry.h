#pragma once
// Name -> factory for pass types. passes/registry.cpp registers every built-in pass.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/graph/pass.h"

namespace diptych {

struct PassTypeInfo {
  std::string name;
  std::string summary;  // one line for --help and docs
  std::function<std::unique_ptr<Pass>()> create;
};

class PassRegistry {
 public:
  void add(PassTypeInfo info);
  template <class P>
  void add(std::string name, std::string summary) {
    add({std::move(name), std::move(summary), [] { return std::make_unique<P>(); }});
  }
  const PassTypeInfo* find(const std::string& name) const;
  std::vector<std::string> names() const;

 private:
  std::map<std::string, PassTypeInfo> types_;
};

}  // namespace diptych
