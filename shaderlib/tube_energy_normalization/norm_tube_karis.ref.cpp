// Reference for norm_tube_karis: Karis 2013, eq. 17 (seed 002), LineNormalization = alpha /
// alpha', with alpha' = saturate(alpha + saturate(sourceLength / distance) / 2) (the seed gives
// no alpha' for the line; UE4's AreaLightSpecular saturates the line angle first),
// multiplied by the sphere's eq. 14, (alpha / saturate(alpha + sourceRadius / (2 distance)))^2,
// "approximating the convolution" of line and sphere by the product. distance: to the centre.
// Ground truth: the tube's GGX D averaged over its solid angle relative to D at its max n.h
// (tube_lights_reference.hpp).
#include "common/tube_lights_reference.hpp"

namespace mb::ref {

static double normTubeKaris(Geometry, double alpha, Vec3 L0, Vec3 L1, double sourceRadius) {
  double distance = length((L0 + L1) * 0.5), sourceLength = length(L1 - L0);
  double lineAngle = clamp01(sourceLength / distance);
  double lineNormalization = alpha / clamp01(alpha + 0.5 * lineAngle);
  double sphereNormalization = std::pow(alpha / clamp01(alpha + sourceRadius / (2.0 * distance)), 2.0);
  return lineNormalization * sphereNormalization;
}

MB_REFERENCE("norm_tube_karis", normTubeKaris);
MB_GROUND_TRUTH("norm_tube_karis", tubes::tubeNormalizationTruth);

}  // namespace mb::ref
