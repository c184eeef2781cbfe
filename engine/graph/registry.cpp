#include "engine/graph/registry.h"

#include <algorithm>

#include "engine/core/error.h"

namespace diptych {

void PassRegistry::add(PassTypeInfo info) {
  if (find(info.name)) throw Error("pass type '" + info.name + "' registered twice");
  types_.push_back(std::move(info));
}

const PassTypeInfo* PassRegistry::find(const std::string& name) const {
  for (const PassTypeInfo& t : types_)
    if (t.name == name) return &t;
  return nullptr;
}

std::vector<std::string> PassRegistry::names() const {
  std::vector<std::string> out;
  for (const PassTypeInfo& t : types_) out.push_back(t.name);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<const PassTypeInfo*> PassRegistry::producersOf(const std::string& slot) const {
  std::vector<const PassTypeInfo*> out;
  for (const PassTypeInfo& t : types_)
    if (t.slot == slot) out.push_back(&t);
  return out;
}

}  // namespace diptych
