#include "bench_engine/pareto.hpp"

#include <algorithm>

#include "bench_engine/cost_interval.hpp"

namespace mb::bench {
namespace {

bool finite(const ParetoPoint& p) { return std::isfinite(p.cost) && std::isfinite(p.error); }

CostInterval interval(const ParetoPoint& p) {
  return {std::isnan(p.costLow) ? p.cost : p.costLow, std::isnan(p.costHigh) ? p.cost : p.costHigh};
}

// a dominates b: a's cost not significantly higher, a's error not higher, and a better in
// one (significantly cheaper, or more accurate). Acyclic: a cycle would need equal errors
// and a strictly decreasing chain of disjoint intervals back to its start.
bool dominates(const ParetoPoint& a, const ParetoPoint& b) {
  const bool cheaper = significantlyCheaper(interval(a), interval(b));
  const bool costlier = significantlyCheaper(interval(b), interval(a));
  return !costlier && a.error <= b.error && (cheaper || a.error < b.error);
}

// The rule without intervals: what the frontier would be if every cost were exact.
bool dominatesNominally(const ParetoPoint& a, const ParetoPoint& b) {
  return a.cost <= b.cost && a.error <= b.error && (a.cost < b.cost || a.error < b.error);
}

}  // namespace

FrontierMarks paretoFrontierWithTies(const std::vector<ParetoPoint>& points) {
  // O(n^2): a slot holds a dozen bricks at most.
  FrontierMarks marks;
  marks.tiedWith.resize(points.size());
  auto dominatedBy = [&](size_t i, auto rule) {
    for (size_t j = 0; j < points.size(); ++j)
      if (j != i && finite(points[j]) && rule(points[j], points[i])) return true;
    return false;
  };
  std::vector<bool> onFrontier(points.size(), false);
  for (size_t i = 0; i < points.size(); ++i)
    if (finite(points[i]) && !dominatedBy(i, dominates)) {
      marks.frontier.push_back(i);
      onFrontier[i] = true;
    }
  // Tied: off the frontier only because a cost difference was within the noise. It ties with
  // the frontier point, as accurate or more, whose cost interval overlaps its own and whose
  // nominal cost is nearest.
  for (size_t i = 0; i < points.size(); ++i) {
    if (onFrontier[i] || !finite(points[i]) || dominatedBy(i, dominatesNominally)) continue;
    std::optional<size_t> best;
    for (size_t j : marks.frontier) {
      const ParetoPoint &p = points[i], &q = points[j];
      if (q.error > p.error || significantlyCheaper(interval(p), interval(q)) ||
          significantlyCheaper(interval(q), interval(p)))
        continue;
      if (!best || std::abs(q.cost - p.cost) < std::abs(points[*best].cost - p.cost)) best = j;
    }
    marks.tiedWith[i] = best;
  }
  std::sort(marks.frontier.begin(), marks.frontier.end(), [&](size_t a, size_t b) {
    const ParetoPoint &p = points[a], &q = points[b];
    if (p.cost != q.cost) return p.cost < q.cost;
    if (p.error != q.error) return p.error < q.error;
    return a < b;
  });
  return marks;
}

std::vector<size_t> paretoFrontier(const std::vector<ParetoPoint>& points) {
  return paretoFrontierWithTies(points).frontier;
}

}  // namespace mb::bench
