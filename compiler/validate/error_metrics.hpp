// Error of GPU (fp32) results against the double reference, reported rather than only
// judged (DESIGN.md "Error is reported"): max abs, max rel (with a floor), max ULP, and
// counts of NaN, Inf and negative GPU values.
#pragma once
#include <cstdint>
#include <string>

#include "library/shader_library.hpp"

namespace mb {

// Relative error is |gpu - ref| / max(|ref|, kRelativeErrorFloor): values whose magnitude
// is below the floor are judged on absolute error.
inline constexpr double kRelativeErrorFloor = 1e-6;

struct ErrorStats {
  uint64_t components = 0;  // output values compared
  uint64_t nanCount = 0;
  uint64_t infCount = 0;
  uint64_t negativeCount = 0;     // negative GPU values among the values added with `radiance`
  uint64_t referenceInvalid = 0;  // reference gave NaN/Inf: a reference bug
  uint64_t failures = 0;          // outside abs + rel * |ref|
  double maxAbs = 0;
  double maxRel = 0;
  double maxUlp = 0;  // over values with |ref| >= kRelativeErrorFloor
  // Largest input-conditioning allowance granted to a value (ProbeRun::conditioning).
  double maxConditioning = 0;
  // Values that pass only thanks to that allowance (outside abs + rel * |ref| alone).
  uint64_t passedByConditioning = 0;
  double worstRatio = -1;    // max |gpu-ref| / allowed over all values
  int64_t worstRecord = -1;  // record index of worstRatio

  // A value passes when |gpu - ref| <= tol.abs + tol.rel * |ref| + conditioning, where
  // `conditioning` is how much the exact result moves under the fp32 rounding of the
  // direction inputs (the problem's own sensitivity, not the brick's arithmetic).
  // `radiance`: the value is radiance, so a negative one is counted (signed values such as a
  // surface's normal are compared but never counted as negative).
  void add(int64_t record, float gpu, double ref, const Tolerance& tol, double conditioning = 0.0,
           bool radiance = true);
  bool passed() const { return failures == 0 && nanCount == 0 && infCount == 0 && referenceInvalid == 0; }
};

// Distance in units in the last place between two floats (reference rounded to float).
double ulpDistance(float a, float b);

}  // namespace mb
