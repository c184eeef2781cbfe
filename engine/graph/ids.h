#pragma once
// Distinct index types of the frame graph, so that a resource id cannot be used where a pass
// index or a pool slot is meant (each is a struct, not an int alias), and IdVector, a vector
// indexed only by its own id type, whose out-of-range access is a DIPTYCH_CHECK failure.
#include <compare>
#include <cstddef>
#include <string>
#include <vector>

#include "engine/core/check.h"

namespace diptych {

template <class Tag>
struct Id {
  int value = -1;  // -1: none
  constexpr Id() = default;
  constexpr explicit Id(int v) : value(v) {}
  constexpr explicit Id(std::size_t v) : value(int(v)) {}
  constexpr bool valid() const { return value >= 0; }
  constexpr auto operator<=>(const Id&) const = default;
};

template <class Tag>
std::string to_string(Id<Tag> id) {
  return std::to_string(id.value);
}

using ResourceId = Id<struct ResourceTag>;  // CompiledGraph::resources; also pass handles
using PassIndex = Id<struct PassTag>;       // CompiledGraph::passes
using PoolSlotId = Id<struct PoolSlotTag>;  // CompiledGraph::pool
inline constexpr ResourceId kNoResource{};

template <class IdType, class T>
class IdVector {
 public:
  T& operator[](IdType id) { return items_[checked(id)]; }
  const T& operator[](IdType id) const { return items_[checked(id)]; }
  bool contains(IdType id) const { return id.valid() && std::size_t(id.value) < items_.size(); }
  std::size_t size() const { return items_.size(); }
  bool empty() const { return items_.empty(); }
  IdType push_back(T item) {
    items_.push_back(std::move(item));
    return IdType(items_.size() - 1);
  }
  IdType lastId() const { return IdType(items_.size() - 1); }
  auto begin() { return items_.begin(); }
  auto end() { return items_.end(); }
  auto begin() const { return items_.begin(); }
  auto end() const { return items_.end(); }
  // Every id in order: for (PassIndex p : g.passes.ids()).
  std::vector<IdType> ids() const {
    std::vector<IdType> out;
    for (std::size_t i = 0; i < items_.size(); ++i) out.push_back(IdType(i));
    return out;
  }

 private:
  std::size_t checked(IdType id) const {
    DIPTYCH_CHECK(contains(id), "id " + std::to_string(id.value) + " of a table of " +
                                    std::to_string(items_.size()));
    return std::size_t(id.value);
  }
  std::vector<T> items_;
};

}  // namespace diptych
