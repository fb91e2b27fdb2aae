// Reference for horizon_wrap_ue4_simple: UE4 SphereHorizonCosWrap, #else branch (seed 002):
//   saturate((n.l + sin^2 a) / (1 + sin^2 a)). Ground truth: the exact sphere irradiance
// ratio (horizon_wrap_accurate's closed form).
#include "common/lights_reference.hpp"

namespace mb::ref {

static double horizonWrapSimple(Geometry g, double sinAlpha) {
  double s2 = sinAlpha * sinAlpha;
  return clamp01((dot(g.n, g.l) + s2) / (1.0 + s2));
}

MB_REFERENCE("horizon_wrap_ue4_simple", horizonWrapSimple);
MB_GROUND_TRUTH("horizon_wrap_ue4_simple", lights::sphereHorizonCosAccurate);

}  // namespace mb::ref
