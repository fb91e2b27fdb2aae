// Reference for falloff_ue4: Karis 2013, eq. 9, saturate(1 - (d/r)^4)^2 / (d^2 + 1),
// written literally with d = |toLight|. Ground truth: the plain inverse square 1 / d^2 it
// windows and biases (the approximation error is the window plus the +1).
#include "common/reference.hpp"

namespace mb::ref {

static double falloffUe4(Vec3 toLight, double lightRadius) {
  double d = length(toLight);
  double window = clamp01(1.0 - std::pow(d / lightRadius, 4.0));
  return window * window / (d * d + 1.0);
}

static double inverseSquare(Vec3 toLight, double) { return 1.0 / dot(toLight, toLight); }

MB_REFERENCE("falloff_ue4", falloffUe4);
MB_GROUND_TRUTH("falloff_ue4", inverseSquare);

}  // namespace mb::ref
