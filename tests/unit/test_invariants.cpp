// The internal-invariant policy (engine/core/check.h): a broken invariant is an InternalError
// naming the source place, the expression and what broke, and the frame graph's id-indexed
// tables refuse an id of the right type but out of range the same way.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/core/check.h"
#include "engine/graph/ids.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;
std::string failure(const std::function<void()>& f) {
  try {
    f();
  } catch (const InternalError& e) {
    return e.what();
  }
  return "";
}

TEST(Invariants, CheckNamesThePlaceTheExpressionAndTheMessage) {
  const int size = 2;
  const std::string what =
      failure([&] { DIPTYCH_CHECK(size > 3, "size is " + std::to_string(size)); });
  EXPECT_EQ(what.rfind("internal error: tests/unit/test_invariants.cpp:", 0), 0u) << what;
  EXPECT_NE(what.find("check 'size > 3' failed: size is 2"), std::string::npos) << what;
  EXPECT_EQ(failure([&] { DIPTYCH_CHECK(size == 2, "unused"); }), "");
}

// The frame graph's index types do not convert into each other or from a bare int.
static_assert(!std::is_convertible_v<PassIndex, ResourceId>);
static_assert(!std::is_convertible_v<ResourceId, PoolSlotId>);
static_assert(!std::is_convertible_v<int, ResourceId>);
static_assert(!std::is_constructible_v<IdVector<PassIndex, int>&, IdVector<ResourceId, int>&>);

TEST(Invariants, IdVectorRefusesIdsOutOfRange) {
  IdVector<PassIndex, int> passes;
  const PassIndex first = passes.push_back(7);
  EXPECT_EQ(first, PassIndex(0));
  EXPECT_EQ(passes[first], 7);
  EXPECT_TRUE(passes.contains(first));
  EXPECT_FALSE(passes.contains(PassIndex()));
  EXPECT_NE(failure([&] { (void)passes[PassIndex(1)]; }).find("id 1 of a table of 1"),
            std::string::npos);
  EXPECT_NE(failure([&] { (void)passes[PassIndex()]; }).find("id -1"), std::string::npos);
  EXPECT_EQ(passes.ids(), std::vector<PassIndex>{first});
}
}  // namespace DIPTYCH_UNITY_ID
