#pragma once
// Wall-clock timing and the summary statistics every reported figure uses.
#include <chrono>
#include <ctime>
#include <vector>

namespace diptych {

class Stopwatch {
 public:
  Stopwatch() : start_(Clock::now()) {}
  void restart() { start_ = Clock::now(); }
  double milliseconds() const {
    return std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

// CPU time of every thread of the process (CLOCK_PROCESS_CPUTIME_ID) since construction. The
// executor runs one node at a time, so over a CPU node this is the node's work on all cores;
// unlike wall time it hardly grows when other processes load the machine (docs/benchmarks.md).
class ProcessCpuClock {
 public:
  ProcessCpuClock() : start_(now()) {}
  double milliseconds() const { return now() - start_; }

 private:
  static double now() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
  }
  double start_;
};

struct TimingStats {
  double median = 0, min = 0, max = 0, mean = 0;
  int samples = 0;
};

// Median is the middle sample (mean of the two middle ones for an even count).
TimingStats summarize(std::vector<double> samples);

}  // namespace diptych
