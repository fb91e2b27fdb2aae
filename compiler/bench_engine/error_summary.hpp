// Approximation error of one brick, permutation or LUT against its yardstick (a ground truth,
// or the brick's own reference where it has none), max and mean over the sampled domain.
//
// The summary metric is the scaled error |x - truth| / max(1, |truth|): BRDF terms span from
// 0 to ~1e5 (GGX D at the peak of a mirror-like lobe, V at grazing angles), so a pure absolute
// error is dominated by the peak and a pure relative error by values near zero, where every
// approximation (and the truth) vanishes. Below 1 it is the absolute error (how results in
// [0, 1] such as Fresnel, the DFG terms or a tonemapped colour are judged), above 1 the
// relative one. Absolute and relative (floor 1e-6, as validate) are reported beside it.
#pragma once
#include <cstdint>

namespace mb::bench {

class ErrorSummary {
 public:
  // Every counter and sum, so that a summary can be stored and restored whole (the report's
  // result cache, bench_engine/result_codec.hpp).
  struct State {
    uint64_t values = 0, finite = 0, nonFinite = 0, truthInvalid = 0;
    double maxAbs = 0, maxRel = 0, maxScaled = 0;
    double sumAbs = 0, sumRel = 0, sumScaled = 0;
  };
  ErrorSummary() = default;
  explicit ErrorSummary(const State& s);
  State state() const;

  // One output value. A non-finite `value` counts in nonFinite (the max becomes +inf); a
  // non-finite `truth` (a yardstick bug) counts in truthInvalid and is skipped.
  void add(double value, double truth);

  uint64_t values() const { return values_; }
  uint64_t nonFinite() const { return nonFinite_; }
  uint64_t truthInvalid() const { return truthInvalid_; }
  double maxAbs() const { return maxAbs_; }
  double maxRel() const { return maxRel_; }
  double maxScaled() const { return maxScaled_; }
  double meanAbs() const { return mean(sumAbs_); }
  double meanRel() const { return mean(sumRel_); }
  double meanScaled() const { return mean(sumScaled_); }

 private:
  double mean(double sum) const;
  uint64_t values_ = 0, finite_ = 0, nonFinite_ = 0, truthInvalid_ = 0;
  double maxAbs_ = 0, maxRel_ = 0, maxScaled_ = 0;
  double sumAbs_ = 0, sumRel_ = 0, sumScaled_ = 0;
};

}  // namespace mb::bench
