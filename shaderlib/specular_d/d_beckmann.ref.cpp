// Reference for d_beckmann: Walter et al. 2007 eq. 25 in pbrt-v4's form
// (BeckmannDistribution): D = exp(-tan^2 theta / alpha^2) / (pi alpha^2 cos^4 theta), with
// tan^2 = inf (h in the tangent plane) giving 0.
#include "common/microfacet_reference.hpp"

namespace mb::ref {

static double dBeckmann(Geometry g, double alpha) {
  double cos2 = g.NoH * g.NoH;
  if (cos2 == 0.0) return 0.0;
  double sin2 = dot(cross(g.n, g.h), cross(g.n, g.h));
  double tan2 = sin2 / cos2;
  return std::exp(-tan2 / (alpha * alpha)) / (kPi * alpha * alpha * cos2 * cos2);
}

MB_REFERENCE("d_beckmann", dBeckmann);

}  // namespace mb::ref
