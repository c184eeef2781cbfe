#pragma once
// A ray count incremented by every tracing thread. One shared std::atomic made every ray pay a
// contended read-modify-write: its cache line bounced between the cores on each increment
// (issue 14's profile of rt_reflection/rt_transmission). Here each thread increments its own
// cache line (a slot picked once per thread) and a read sums the slots.
#include <array>
#include <atomic>
#include <cstdint>

namespace diptych {

class RayCounter {
 public:
  void add(std::uint64_t n) const {
    slots_[threadSlot()].n.fetch_add(n, std::memory_order_relaxed);
  }
  std::uint64_t total() const {
    std::uint64_t sum = 0;
    for (const Slot& s : slots_) sum += s.n.load(std::memory_order_relaxed);
    return sum;
  }
  void reset() const {
    for (Slot& s : slots_) s.n.store(0, std::memory_order_relaxed);
  }

 private:
  static constexpr unsigned kSlots = 32;  // more threads than slots share slots, still correct
  struct alignas(64) Slot {
    std::atomic<std::uint64_t> n{0};
  };
  static unsigned threadSlot() {
    static std::atomic<unsigned> next{0};
    thread_local const unsigned mine = next.fetch_add(1, std::memory_order_relaxed) % kSlots;
    return mine;
  }
  mutable std::array<Slot, kSlots> slots_{};
};

}  // namespace diptych
