#include "bench/pareto.hpp"

#include <algorithm>
#include <cmath>

namespace mb::bench {
namespace {

bool finite(const ParetoPoint& p) { return std::isfinite(p.cost) && std::isfinite(p.error); }

bool dominates(const ParetoPoint& a, const ParetoPoint& b) {
  return a.cost <= b.cost && a.error <= b.error && (a.cost < b.cost || a.error < b.error);
}

}  // namespace

std::vector<size_t> paretoFrontier(const std::vector<ParetoPoint>& points) {
  // O(n^2): a slot holds a dozen bricks at most.
  std::vector<size_t> front;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!finite(points[i])) continue;
    bool dominated = false;
    for (size_t j = 0; j < points.size() && !dominated; ++j)
      dominated = j != i && finite(points[j]) && dominates(points[j], points[i]);
    if (!dominated) front.push_back(i);
  }
  std::sort(front.begin(), front.end(), [&](size_t a, size_t b) {
    const ParetoPoint &p = points[a], &q = points[b];
    if (p.cost != q.cost) return p.cost < q.cost;
    if (p.error != q.error) return p.error < q.error;
    return a < b;
  });
  return front;
}

}  // namespace mb::bench
