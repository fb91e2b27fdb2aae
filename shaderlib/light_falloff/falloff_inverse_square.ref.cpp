// Reference for falloff_inverse_square: E / I = 1 / d^2 with d = |toLight| (Karis 2013, p. 11).
#include "common/reference.hpp"

namespace mb::ref {

static double falloffInverseSquare(Vec3 toLight, double) {
  double d = length(toLight);
  return 1.0 / (d * d);
}

MB_REFERENCE("falloff_inverse_square", falloffInverseSquare);

}  // namespace mb::ref
