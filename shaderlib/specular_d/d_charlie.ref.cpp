// Reference for d_charlie: Estevez & Kulla 2017 eq. 2, D = (2 + 1/r) sin^(1/r)(theta) / (2 pi),
// normalized so that the projected area integral of D is 1.
#include "common/reference.hpp"

namespace mb::ref {

static double dCharlie(Geometry g, double r) {
  double sinTheta = length(cross(g.n, g.h));
  return (2.0 + 1.0 / r) * std::pow(sinTheta, 1.0 / r) / (2.0 * kPi);
}

MB_REFERENCE("d_charlie", dCharlie);

}  // namespace mb::ref
