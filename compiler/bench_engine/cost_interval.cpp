#include "bench_engine/cost_interval.hpp"

#include <algorithm>
#include <cmath>

namespace mb::bench {

double orderStatisticCoverage(size_t n, size_t k) {
  // P(B <= k - 1) for B ~ Binomial(n, 1/2), summed in log space (n may be up to 1000).
  double tail = 0;
  for (size_t i = 0; i < k; ++i) {
    double logC = std::lgamma(double(n) + 1) - std::lgamma(double(i) + 1) - std::lgamma(double(n - i) + 1);
    tail += std::exp(logC - double(n) * std::log(2.0));
  }
  return std::max(0.0, 1.0 - 2.0 * tail);
}

MedianInterval medianInterval(std::vector<double> v, double level) {
  MedianInterval m;
  m.samples = v.size();
  if (v.empty()) return m;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  m.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  // Largest k (narrowest interval) whose coverage still reaches the level; k = 1 at least.
  size_t k = 1;
  while (2 * (k + 1) <= n + 1 && orderStatisticCoverage(n, k + 1) >= level) ++k;
  m.low = v[k - 1];
  m.high = v[n - k];
  m.confidence = orderStatisticCoverage(n, k);
  return m;
}

bool separatedFromEmptyLoop(const MedianInterval& net, double resolution, double level) {
  return net.samples > 0 && net.confidence >= level && net.low > resolution && std::isfinite(net.high);
}

bool significantlyCheaper(const CostInterval& a, const CostInterval& b) { return a.high < b.low; }

}  // namespace mb::bench
