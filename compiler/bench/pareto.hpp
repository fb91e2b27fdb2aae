// The Pareto frontier of (cost, error) points: the choices no other choice beats on both
// axes at once. Along it, each step to a costlier point buys a smaller error; everything off
// it is dominated (something is at most as costly and at most as wrong, and better in one).
#pragma once
#include <cstddef>
#include <vector>

namespace mb::bench {

struct ParetoPoint {
  double cost = 0;   // lower is better (ns per evaluation)
  double error = 0;  // lower is better (max error)
};

// Indices of the non-dominated points, by increasing cost (ties: increasing error, then
// index). Points with a non-finite coordinate are never on the frontier and never dominate.
// Equal points do not dominate each other: both are on the frontier.
std::vector<size_t> paretoFrontier(const std::vector<ParetoPoint>& points);

}  // namespace mb::bench
