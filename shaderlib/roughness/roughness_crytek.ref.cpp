// Reference for roughness_crytek: Crytek's remap as quoted by Lagarde & de Rousiers 2014,
// alpha^2 = (1 - 0.7 * smoothness)^6 with smoothness = 1 - perceptual roughness; alpha is the
// square root of that.
#include "common/reference.hpp"

namespace mb::ref {

static double roughnessCrytek(double perceptualRoughness) {
  double smoothness = 1.0 - perceptualRoughness;
  double alphaSquared = std::pow(1.0 - 0.7 * smoothness, 6.0);
  return std::sqrt(alphaSquared);
}

MB_REFERENCE("roughness_crytek", roughnessCrytek);

}  // namespace mb::ref
