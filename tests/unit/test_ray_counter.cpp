// RayCounter (engine/rt/ray_counter.h): threads with a slot of their own count with a plain
// load and store, later threads share one slot atomically. Either way every count is kept.
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "engine/rt/ray_counter.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

TEST(RayCounter, EveryThreadsCountsAreKeptBeyondTheExclusiveSlots) {
  RayCounter counter;
  constexpr int kThreads = 48;  // more than the 31 exclusive slots: some share the last one
  constexpr int kAdds = 20000;
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&counter, t] {
      for (int i = 0; i < kAdds; ++i) counter.add(std::uint64_t(t % 3 + 1));
    });
  for (std::thread& t : threads) t.join();
  std::uint64_t expected = 0;
  for (int t = 0; t < kThreads; ++t) expected += std::uint64_t(t % 3 + 1) * kAdds;
  EXPECT_EQ(counter.total(), expected);
  counter.reset();
  EXPECT_EQ(counter.total(), 0u);
  counter.add(7);
  EXPECT_EQ(counter.total(), 7u);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
