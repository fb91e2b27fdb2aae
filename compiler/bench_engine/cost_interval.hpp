// Confidence interval of a median from independent repeats, and the rule that decides when a
// measured cost is separated from the empty loop at all.
//
// Why order statistics and not a t-interval or a bootstrap: the repeats' run times on a
// loaded machine are skewed and heavy-tailed (time is only ever added to a dispatch, never
// taken away), so a mean +- t s interval is dominated by the outliers, and a bootstrap of 9
// values resamples the same few points (and is random). The distribution-free interval for
// the median from order statistics needs nothing but independence: with the n samples
// sorted, [x(k), x(n+1-k)] covers the population median with probability
// 1 - 2 P(B <= k - 1), B ~ Binomial(n, 1/2) (Conover, "Practical Nonparametric Statistics",
// 3rd ed., section 3.2; Hollander & Wolfe). It is exact, deterministic and cheap.
#pragma once
#include <cstddef>
#include <vector>

namespace mb::bench {

inline constexpr double kCostConfidence = 0.95;

struct MedianInterval {
  double median = 0;
  double low = 0, high = 0;  // [x(k), x(n+1-k)]
  double confidence = 0;     // its exact coverage, >= the level asked for when n allows it
  size_t samples = 0;
};

// The narrowest order-statistic interval whose coverage reaches `level`; with too few
// samples for that (n <= 5 at 95 %), [min, max] and its lower coverage (0 for n = 1).
// Empty input: all zeros.
MedianInterval medianInterval(std::vector<double> samples, double level = kCostConfidence);

// Coverage of [x(k), x(n+1-k)] for n samples (k >= 1, 2k <= n + 1).
double orderStatisticCoverage(size_t n, size_t k);

// A cost is resolved when its interval reached the level and its lower end, per dispatch,
// exceeds the timer's resolution over that dispatch: only then is the kernel measurably
// slower than the empty loop. Otherwise it is reported as "below resolution".
bool separatedFromEmptyLoop(const MedianInterval& netPerDispatch, double resolutionPerDispatch,
                            double level = kCostConfidence);

// Two costs differ significantly when their intervals do not overlap. For two independent
// 95 % intervals of about equal width that is a test at well under 1 % (the difference has
// to exceed about 2.8 standard errors, not 1.96): conservative, which is what a frontier
// should be about noise.
struct CostInterval {
  double low = 0, high = 0;
};
bool significantlyCheaper(const CostInterval& a, const CostInterval& b);

}  // namespace mb::bench
