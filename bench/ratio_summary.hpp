// Ratios of an approximation to its ground truth, summarized for the area-light benches
// (bench_area_lights.cpp, area_lights_ltc.cpp): quantiles of the ratio and of |ratio - 1|, and
// the configurations of the extremes.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace mb::bench {

// A figure of the benches' Markdown tables: three significant digits.
inline std::string threeDigits(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

// ratio = approximation / truth, summarized.
struct Summary {
  std::vector<double> ratios;
  std::string minAt, maxAt;  // the configurations of the extreme ratios
  void add(double ratio, const std::string& where) {
    auto [lo, hi] = std::minmax_element(ratios.begin(), ratios.end());
    if (ratios.empty() || ratio < *lo) minAt = where;
    if (ratios.empty() || ratio > *hi) maxAt = where;
    ratios.push_back(ratio);
  }
  nlohmann::json toJson() const {
    std::vector<double> r = ratios;
    std::sort(r.begin(), r.end());
    auto q = [&](double p) { return r.empty() ? 0.0 : r[std::min(r.size() - 1, size_t(p * (r.size() - 1) + 0.5))]; };
    double maxRel = 0, meanRel = 0;
    std::vector<double> dev;
    for (double x : r)
      maxRel = std::max(maxRel, std::fabs(x - 1)), meanRel += std::fabs(x - 1), dev.push_back(std::fabs(x - 1));
    if (!r.empty()) meanRel /= r.size();
    std::sort(dev.begin(), dev.end());
    auto qd = [&](double p) {
      return dev.empty() ? 0.0 : dev[std::min(dev.size() - 1, size_t(p * (dev.size() - 1) + 0.5))];
    };
    return {{"samples", r.size()},       {"max_rel_error", maxRel}, {"mean_rel_error", meanRel},
            {"ratio_p05", q(0.05)},      {"ratio_median", q(0.5)},  {"ratio_p95", q(0.95)},
            {"ratio_min", q(0.0)},       {"ratio_max", q(1.0)},     {"rel_error_median", qd(0.5)},
            {"rel_error_p95", qd(0.95)}, {"min_at", minAt},         {"max_at", maxAt}};
  }
};

}  // namespace mb::bench
