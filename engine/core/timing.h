#pragma once
// Wall-clock timing and the summary statistics every reported figure uses.
#include <chrono>
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

struct TimingStats {
  double median = 0, min = 0, max = 0, mean = 0;
  int samples = 0;
};

// Median is the middle sample (mean of the two middle ones for an even count).
TimingStats summarize(std::vector<double> samples);

}  // namespace diptych
