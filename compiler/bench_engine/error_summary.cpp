#include "bench_engine/error_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "validate/error_metrics.hpp"

namespace mb::bench {

ErrorSummary::ErrorSummary(const State& s)
    : values_(s.values),
      finite_(s.finite),
      nonFinite_(s.nonFinite),
      truthInvalid_(s.truthInvalid),
      maxAbs_(s.maxAbs),
      maxRel_(s.maxRel),
      maxScaled_(s.maxScaled),
      sumAbs_(s.sumAbs),
      sumRel_(s.sumRel),
      sumScaled_(s.sumScaled) {}

ErrorSummary::State ErrorSummary::state() const {
  return {values_, finite_, nonFinite_, truthInvalid_, maxAbs_, maxRel_, maxScaled_, sumAbs_, sumRel_, sumScaled_};
}

void ErrorSummary::add(double value, double truth) {
  if (!std::isfinite(truth)) {
    ++truthInvalid_;
    return;
  }
  ++values_;
  if (!std::isfinite(value)) {
    ++nonFinite_;
    maxAbs_ = maxRel_ = maxScaled_ = std::numeric_limits<double>::infinity();
    return;
  }
  ++finite_;
  double e = std::abs(value - truth), t = std::abs(truth);
  double rel = e / std::max(t, kRelativeErrorFloor), scaled = e / std::max(t, 1.0);
  maxAbs_ = std::max(maxAbs_, e);
  maxRel_ = std::max(maxRel_, rel);
  maxScaled_ = std::max(maxScaled_, scaled);
  sumAbs_ += e;
  sumRel_ += rel;
  sumScaled_ += scaled;
}

// Means are over the finite values; nonFinite says how many were left out.
double ErrorSummary::mean(double sum) const { return finite_ ? sum / double(finite_) : 0.0; }

}  // namespace mb::bench
