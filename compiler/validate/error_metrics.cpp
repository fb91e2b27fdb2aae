#include "validate/error_metrics.hpp"

#include <bit>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace mb {

double ulpDistance(float a, float b) {
  if (std::isnan(a) || std::isnan(b)) return std::numeric_limits<double>::infinity();
  // Map the float bit patterns onto a monotonic integer line.
  auto ordered = [](float f) {
    int32_t i = std::bit_cast<int32_t>(f);
    return i < 0 ? static_cast<int64_t>(INT32_MIN) - i : static_cast<int64_t>(i);
  };
  return static_cast<double>(std::llabs(ordered(a) - ordered(b)));
}

void ErrorStats::add(int64_t record, float gpu, double ref, const Tolerance& tol, double conditioning, bool radiance) {
  ++components;
  if (!std::isfinite(ref)) {
    ++referenceInvalid;
    return;
  }
  if (std::isnan(gpu)) {
    ++nanCount;
    worstRecord = worstRatio == std::numeric_limits<double>::infinity() ? worstRecord : record;
    worstRatio = std::numeric_limits<double>::infinity();
    return;
  }
  if (std::isinf(gpu)) {
    ++infCount;
    worstRecord = worstRatio == std::numeric_limits<double>::infinity() ? worstRecord : record;
    worstRatio = std::numeric_limits<double>::infinity();
    return;
  }
  if (radiance && gpu < 0.0f) ++negativeCount;
  double err = std::abs(static_cast<double>(gpu) - ref);
  double arithmetic = tol.abs + tol.rel * std::abs(ref);
  double allowed = arithmetic + conditioning;
  maxConditioning = std::max(maxConditioning, conditioning);
  if (err > arithmetic && err <= allowed) ++passedByConditioning;
  maxAbs = std::max(maxAbs, err);
  maxRel = std::max(maxRel, err / std::max(std::abs(ref), kRelativeErrorFloor));
  // ULPs are meaningful only away from zero: below the floor, values are judged on abs error.
  if (std::abs(ref) >= kRelativeErrorFloor) maxUlp = std::max(maxUlp, ulpDistance(gpu, static_cast<float>(ref)));
  if (err > allowed) ++failures;
  double ratio = allowed > 0 ? err / allowed : (err > 0 ? std::numeric_limits<double>::max() : 0.0);
  if (ratio > worstRatio) {
    worstRatio = ratio;
    worstRecord = record;
  }
}

}  // namespace mb
