// Reference for d_ggx_aniso: the anisotropic Trowbridge-Reitz NDF in pbrt-v4's form
// (TrowbridgeReitzDistribution::D, after Heitz 2014 eq. 85):
//   D(h) = 1 / (pi at ab cos^4(theta_h) (1 + tan^2(theta_h) (cos^2(phi_h)/at^2 + sin^2(phi_h)/ab^2))^2)
// with theta_h, phi_h the angles of h in the Gram-Schmidt frame of (n, t) and tan^2 = inf
// (h in the tangent plane) giving 0.
#include "common/aniso_reference.hpp"

namespace mb::ref {

static double dGgxAniso(Geometry g, Vec3 tangent, double at, double ab) {
  LocalAngles h = localAngles(anisoFrame(g.n, tangent), g.h, g.NoH);
  if (std::isinf(h.tan2Theta)) return 0.0;
  double e = h.tan2Theta * (h.cos2Phi / (at * at) + h.sin2Phi / (ab * ab));
  return 1.0 / (kPi * at * ab * h.cos2Theta * h.cos2Theta * (1.0 + e) * (1.0 + e));
}

MB_REFERENCE("d_ggx_aniso", dGgxAniso);

}  // namespace mb::ref
