// Reference for horizon_wrap_hermite: UE4 SphereHorizonCosWrap (Hermite branch, seed 002):
//   n.l < sin a:  n.l = max(n.l, -sin a);  n.l = (sin a + n.l)^2 / (4 sin a).
// Ground truth: the exact irradiance of the sphere normalized by that of a facing point light
// of the same intensity, in the closed form of horizon_wrap_accurate (Snyder 1996).
#include "common/lights_reference.hpp"

namespace mb::ref {

static double horizonWrapHermite(Geometry g, double sinAlpha) {
  double NoL = dot(g.n, g.l);
  if (NoL >= sinAlpha) return NoL;
  if (sinAlpha == 0.0) return 0.0;  // point light below the horizon (the source's 0/0)
  NoL = std::max(NoL, -sinAlpha);
  return (sinAlpha + NoL) * (sinAlpha + NoL) / (4.0 * sinAlpha);
}

MB_REFERENCE("horizon_wrap_hermite", horizonWrapHermite);
MB_GROUND_TRUTH("horizon_wrap_hermite", lights::sphereHorizonCosAccurate);

}  // namespace mb::ref
