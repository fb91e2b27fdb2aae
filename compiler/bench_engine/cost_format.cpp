#include "bench_engine/cost_format.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace mb::bench {

std::string formatDuration(double ns) {
  if (!std::isfinite(ns) || ns <= 0) return "n/a";
  // printf rounds to three significant digits first, so 999.6 ps comes out as 1.00e+00 ns
  // and picks the next unit, never "1000 ps".
  char b[32];
  std::snprintf(b, sizeof b, "%.2e", ns);  // d.dde[+-]XX
  const std::string digits = std::string(1, b[0]) + b[2] + b[3];
  const int exponent = std::atoi(b + 5);
  static constexpr const char* kUnits[] = {"fs", "ps", "ns", "µs", "ms", "s"};
  int unit = static_cast<int>(std::floor((exponent + 6) / 3.0));  // 0 = fs (1e-6 ns)
  unit = unit < 0 ? 0 : unit > 5 ? 5 : unit;
  const int before = exponent - (3 * unit - 6) + 1;  // digits before the point: 1..3 in range
  std::string text;
  if (before <= 0)
    text = digits.substr(0, 1) + "." + digits.substr(1) + "e" + std::to_string(before - 1);  // below 1 fs
  else if (before >= 3)
    text = digits + std::string(size_t(before - 3), '0');  // 100 .. beyond 999 s
  else
    text = digits.substr(0, size_t(before)) + "." + digits.substr(size_t(before));
  return text + " " + kUnits[unit];
}

std::string formatCost(const CostMeasurement& m) {
  return m.resolved ? formatDuration(m.nsPerEval) : "below resolution";
}

std::string formatCostWithInterval(const CostMeasurement& m) {
  if (!m.resolved) return "below resolution (< " + formatDuration(m.nsUpperBound()) + ")";
  return formatDuration(m.nsPerEval) + " (" + formatDuration(m.nsPerEvalLow) + " to " +
         formatDuration(m.nsPerEvalHigh) + ")";
}

}  // namespace mb::bench
