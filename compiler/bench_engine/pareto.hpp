// The Pareto frontier of (cost, error) points: the choices no other choice beats on both
// axes at once. Along it, each step to a costlier point buys a smaller error; everything off
// it is dominated (something is at most as costly and at most as wrong, and better in one).
//
// Costs are measured, so each carries a confidence interval; errors are computed on fixed
// samples and compared exactly. A cost only counts as lower where its interval lies wholly
// below the other's (bench_engine/cost_interval.hpp significantlyCheaper); overlapping intervals
// are a tie in cost, which the more accurate point wins. So a point joins the frontier only
// where its cost differs significantly from the points it would otherwise step past, and a
// point the classic rule keeps but the tie removes is reported as tied with the frontier
// point that wins the tie.
#pragma once
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace mb::bench {

struct ParetoPoint {
  double cost = 0;   // lower is better (nominal: the median)
  double error = 0;  // lower is better (max error)
  // The cost's confidence interval; NaN (the default) means exactly `cost`.
  double costLow = NAN, costHigh = NAN;
};

struct FrontierMarks {
  std::vector<size_t> frontier;                 // by increasing cost (then error, index)
  std::vector<std::optional<size_t>> tiedWith;  // per point: the frontier point it ties with
};

// Points with a non-finite cost or error are never on the frontier and never dominate.
// Equal points do not dominate each other: both are on the frontier.
FrontierMarks paretoFrontierWithTies(const std::vector<ParetoPoint>& points);
std::vector<size_t> paretoFrontier(const std::vector<ParetoPoint>& points);

}  // namespace mb::bench
