// Reference for d_ggx: Walter et al. 2007, eq. 33, in the tan^2 form of pbrt-v4
// (TrowbridgeReitzDistribution::D):
//   D(h) = 1 / (pi * alpha^2 * cos^4(theta_h) * (1 + tan^2(theta_h) / alpha^2)^2)
#include "common/reference.hpp"

namespace mb::ref {

static double dGgx(const Geometry& g, double alpha) {
  double cos2 = g.NoH * g.NoH;
  // h in the tangent plane: tan^2 is infinite, but cos^4 (1 + tan^2 / alpha^2)^2 =
  // (cos^2 + sin^2 / alpha^2)^2 -> 1 / alpha^4, so D -> alpha^2 / pi (not 0).
  if (cos2 == 0.0) return alpha * alpha / kPi;
  double tan2 = (1.0 - cos2) / cos2;
  double e = 1.0 + tan2 / (alpha * alpha);
  return 1.0 / (kPi * alpha * alpha * cos2 * cos2 * e * e);
}

MB_REFERENCE("d_ggx", dGgx);

}  // namespace mb::ref
