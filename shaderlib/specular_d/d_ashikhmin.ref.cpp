// Reference for d_ashikhmin: Ashikhmin & Premoze 2007 inverted-Gaussian velvet distribution,
// normalized as in Neubelt & Pettineo 2013:
//   D = 1/(pi (1 + 4 alpha^2)) (1 + 4 exp(-cot^2 theta / alpha^2) / sin^4 theta)
// with the sin theta = 0 limit (the exponential dominates) returned explicitly.
#include "common/reference.hpp"

namespace mb::ref {

static double dAshikhmin(Geometry g, double alpha) {
  double cosTheta = g.NoH;
  double sinTheta = length(cross(g.n, g.h));
  double normalization = 1.0 / (kPi * (1.0 + 4.0 * alpha * alpha));
  if (sinTheta == 0.0) return normalization;  // exp(-cot^2/alpha^2)/sin^4 -> 0
  double cot = cosTheta / sinTheta;
  double sin4 = std::pow(sinTheta, 4.0);
  return normalization * (1.0 + 4.0 * std::exp(-cot * cot / (alpha * alpha)) / sin4);
}

MB_REFERENCE("d_ashikhmin", dAshikhmin);

}  // namespace mb::ref
