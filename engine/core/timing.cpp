#include "engine/core/timing.h"

#include <algorithm>
#include <numeric>

namespace diptych {
TimingStats summarize(std::vector<double> s) {
  TimingStats t;
  t.samples = int(s.size());
  if (s.empty()) return t;
  std::sort(s.begin(), s.end());
  const std::size_t n = s.size();
  t.median = n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
  t.min = s.front();
  t.max = s.back();
  t.mean = std::accumulate(s.begin(), s.end(), 0.0) / double(n);
  return t;
}
}  // namespace diptych
