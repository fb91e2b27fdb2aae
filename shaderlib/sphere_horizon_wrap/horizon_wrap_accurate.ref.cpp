// Reference for horizon_wrap_accurate: UE4 SphereHorizonCosWrap, accurate branch (seed 002),
// literally in double (lights_reference.hpp). Ground truth: the sphere's irradiance over that
// of a facing point light, (1 / (pi sin^2 a)) Int_cap max(n.l, 0) dw, integrated numerically.
#include "common/lights_reference.hpp"

namespace mb::ref {

static double horizonWrapAccurate(Geometry g, double sinAlpha) { return lights::sphereHorizonCosAccurate(g, sinAlpha); }

static double horizonWrapTruth(Geometry g, double sinAlpha) { return lights::sphereIrradianceOverPoint(g, sinAlpha); }

MB_REFERENCE("horizon_wrap_accurate", horizonWrapAccurate);
MB_GROUND_TRUTH("horizon_wrap_accurate", horizonWrapTruth);

}  // namespace mb::ref
