// Reference for d_beckmann_aniso: the anisotropic Beckmann NDF in pbrt-v3's form
// (BeckmannDistribution::D, after Walter et al. 2007 eq. 25 and Heitz 2014 eq. 84):
//   D(h) = exp(-tan^2(theta_h) (cos^2(phi_h)/at^2 + sin^2(phi_h)/ab^2)) / (pi at ab cos^4(theta_h))
// tan^2 = inf (h in the tangent plane) gives 0.
#include "common/aniso_reference.hpp"

namespace mb::ref {

static double dBeckmannAniso(Geometry g, Vec3 tangent, double at, double ab) {
  LocalAngles h = localAngles(anisoFrame(g.n, tangent), g.h, g.NoH);
  if (std::isinf(h.tan2Theta)) return 0.0;
  double e = h.tan2Theta * (h.cos2Phi / (at * at) + h.sin2Phi / (ab * ab));
  return std::exp(-e) / (kPi * at * ab * h.cos2Theta * h.cos2Theta);
}

MB_REFERENCE("d_beckmann_aniso", dBeckmannAniso);

}  // namespace mb::ref
