// What every benchmark program reports alike: medians of repeats, and the machine's load average
// before and after (the VMs are shared and noisy; bench/README.md).
#pragma once
#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

namespace mb::bench {

// The median of `v` (the mean of the middle two for an even count); 0 for none.
inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The first line of /proc/loadavg: the 1, 5 and 15 minute load averages and the run queue.
inline std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string line;
  std::getline(in, line);
  return line;
}

}  // namespace mb::bench
