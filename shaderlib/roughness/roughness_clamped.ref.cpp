// Reference for roughness_clamped: Filament's perceptual-roughness floor of 0.045 (fp32),
// then the Burley/Karis square: alpha = max(0.045, min(r, 1))^2.
#include <algorithm>

#include "common/reference.hpp"

namespace mb::ref {

static double roughnessClamped(double perceptualRoughness) {
  const double kMinPerceptualRoughness = 0.045;
  double r = std::min(1.0, std::max(kMinPerceptualRoughness, perceptualRoughness));
  return r * r;
}

MB_REFERENCE("roughness_clamped", roughnessClamped);

}  // namespace mb::ref
