// Reference for norm_sphere_karis: Karis 2013, eq. 14, SphereNormalization = (alpha/alpha')^2,
// alpha' = saturate(alpha + sourceRadius / (2 distance)) (UE4 DeferredLightingCommon).
// Ground truth: the factor that makes D at the max-n.h point equal the sphere's integrated D,
// D_eff / D(max n.h) (lights_reference.hpp).
#include "common/lights_reference.hpp"

namespace mb::ref {

static double normSphereKaris(Geometry, double alpha, double sinAlpha) {
  const double distance = 1.0, sourceRadius = sinAlpha * distance;
  double alphaPrime = clamp01(alpha + sourceRadius / (2.0 * distance));
  return std::pow(alpha / alphaPrime, 2.0);
}

MB_REFERENCE("norm_sphere_karis", normSphereKaris);
MB_GROUND_TRUTH("norm_sphere_karis", lights::sphereNormalizationTruth);

}  // namespace mb::ref
