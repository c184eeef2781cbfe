#pragma once
// A ray count incremented by every tracing thread. One shared std::atomic made every ray pay a
// contended read-modify-write: its cache line bounced between the cores on each increment
// (issue 14's profile of rt_reflection/rt_transmission). Here each thread increments its own
// cache line (a slot picked once per thread) and a read sums the slots.
#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>

namespace diptych {

class RayCounter {
 public:
  void add(std::uint64_t n) const {
    const unsigned s = threadSlot();
    Slot& slot = slots_[s];
    // A thread with a slot of its own is its only writer: a relaxed load and store, not a locked
    // read-modify-write (two per traced ray in the Whitted tracer, each a full barrier that
    // held back the ray's other loads and stores). Readers still see a whole value. Threads
    // beyond the exclusive slots share the last one atomically.
    if (s < kExclusive)
      slot.n.store(slot.n.load(std::memory_order_relaxed) + n, std::memory_order_relaxed);
    else
      slot.n.fetch_add(n, std::memory_order_relaxed);
  }
  std::uint64_t total() const {
    std::uint64_t sum = 0;
    for (const Slot& s : slots_) sum += s.n.load(std::memory_order_relaxed);
    return sum;
  }
  // Not concurrently with add(): an owner's load-add-store could write back a count from
  // before the reset.
  void reset() const {
    for (Slot& s : slots_) s.n.store(0, std::memory_order_relaxed);
  }

 private:
  static constexpr unsigned kSlots = 32;
  static constexpr unsigned kExclusive = kSlots - 1;  // slots 0..30: one thread each
  struct alignas(64) Slot {
    std::atomic<std::uint64_t> n{0};
  };
  // The n-th thread that ever counts gets slot n for good (the same in every counter), or the
  // shared last slot once the exclusive ones are taken.
  static unsigned threadSlot() {
    static std::atomic<unsigned> next{0};
    thread_local const unsigned mine =
        std::min(next.fetch_add(1, std::memory_order_relaxed), kExclusive);
    return mine;
  }
  mutable std::array<Slot, kSlots> slots_{};
};

}  // namespace diptych
