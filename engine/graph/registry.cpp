#include "engine/graph/registry.h"

#include "engine/core/error.h"

namespace diptych {

void PassRegistry::add(PassTypeInfo info) {
  const std::string name = info.name;
  if (!types_.emplace(name, std::move(info)).second)
    throw Error("pass type '" + name + "' registered twice");
}

const PassTypeInfo* PassRegistry::find(const std::string& name) const {
  auto it = types_.find(name);
  return it == types_.end() ? nullptr : &it->second;
}

std::vector<std::string> PassRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& [name, info] : types_) out.push_back(name);
  return out;
}

}  // namespace diptych
