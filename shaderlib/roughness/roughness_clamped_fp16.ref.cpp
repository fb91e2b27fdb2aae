// Reference for roughness_clamped_fp16: Filament's half-precision perceptual-roughness floor
// of 0.089, then alpha = r^2.
#include <algorithm>

#include "common/reference.hpp"

namespace mb::ref {

static double roughnessClampedFp16(double perceptualRoughness) {
  const double kMinPerceptualRoughnessFp16 = 0.089;
  double r = std::min(1.0, std::max(kMinPerceptualRoughnessFp16, perceptualRoughness));
  return r * r;
}

MB_REFERENCE("roughness_clamped_fp16", roughnessClampedFp16);

}  // namespace mb::ref
