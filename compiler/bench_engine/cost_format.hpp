// Costs as text: three significant digits in the unit that fits (fs, ps, ns, µs, ms, s), and
// never a zero or negative number: a cost the measurement cannot separate from the empty
// loop is "below resolution" with the bound it is below.
#pragma once
#include <string>

#include "bench_engine/cost.hpp"

namespace mb::bench {

// `ns` > 0 and finite: e.g. 0.000712 -> "712 fs", 0.9996 -> "1.00 ns", 1234.5 -> "1.23 µs";
// below 1 fs in scientific notation ("1.00e-3 fs"), beyond 999 s in whole seconds.
// Anything else (0, negative, NaN, Inf) is not a duration: "n/a".
std::string formatDuration(double ns);

// "1.23 ns", or "below resolution".
std::string formatCost(const CostMeasurement& m);
// "1.23 ns (1.20 ns to 1.27 ns)", or "below resolution (< 12.3 ps)".
std::string formatCostWithInterval(const CostMeasurement& m);

}  // namespace mb::bench
