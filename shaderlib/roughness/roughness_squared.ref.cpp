// Reference for roughness_squared: Karis 2013 (after Burley 2012), alpha = roughness^2.
#include "common/reference.hpp"

namespace mb::ref {

static double roughnessSquared(double perceptualRoughness) { return std::pow(perceptualRoughness, 2.0); }

MB_REFERENCE("roughness_squared", roughnessSquared);

}  // namespace mb::ref
