#pragma once
// A ray count incremented by every tracing thread. One shared std::atomic made every ray pay a
// contended read-modify-write: its cache line bounced between the cores on each increment
// (issue 14's profile of rt_reflection/rt_transmission). Here each thread increments its own
// cache line (a slot picked once per thread) and a read sums the slots. The first kSlots
// threads of the process own their slot alone, so they add with a plain load and store (no
// locked read-modify-write: the tracers add two to four times per pixel ray); any later thread
// shares one atomic overflow slot.
#include <array>
#include <atomic>
#include <cstdint>

namespace diptych {

class RayCounter {
 public:
  void add(std::uint64_t n) const {
    const unsigned slot = threadSlot();
    if (slot >= kSlots) {
      overflow_.n.fetch_add(n, std::memory_order_relaxed);
      return;
    }
    std::atomic<std::uint64_t>& mine = slots_[slot].n;  // written by this thread only
    mine.store(mine.load(std::memory_order_relaxed) + n, std::memory_order_relaxed);
  }
  std::uint64_t total() const {
    std::uint64_t sum = overflow_.n.load(std::memory_order_relaxed);
    for (const Slot& s : slots_) sum += s.n.load(std::memory_order_relaxed);
    return sum;
  }
  void reset() const {  // not concurrent with add (as before: a reset between frames)
    for (Slot& s : slots_) s.n.store(0, std::memory_order_relaxed);
    overflow_.n.store(0, std::memory_order_relaxed);
  }

 private:
  static constexpr unsigned kSlots = 64;
  struct alignas(64) Slot {
    std::atomic<std::uint64_t> n{0};
  };
  // Process-wide: a thread's slot is the same in every counter, and no two threads share one.
  static unsigned threadSlot() {
    static std::atomic<unsigned> next{0};
    thread_local const unsigned mine = next.fetch_add(1, std::memory_order_relaxed);
    return mine;
  }
  mutable std::array<Slot, kSlots> slots_{};
  mutable Slot overflow_;
};

}  // namespace diptych
