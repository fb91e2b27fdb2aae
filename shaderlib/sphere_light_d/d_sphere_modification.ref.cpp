// Reference for d_sphere_modification: Karis 2013, eq. 10, D_GGX(n.h; alpha') with
// alpha' = saturate(alpha + sourceRadius / (3 distance)) (seed 002), D in pbrt's tan^2 form.
// Ground truth: the sphere light's effective D, (1 / (pi sin^2 a)) Int_cap D(n.h(l)) dw
// (lights_reference.hpp), the D a point light of the sphere's intensity would need.
#include "common/lights_reference.hpp"

namespace mb::ref {

static double dSphereModification(Geometry g, double alpha, double sinAlpha) {
  const double distance = 1.0, sourceRadius = sinAlpha * distance;
  double alphaPrime = clamp01(alpha + sourceRadius / (3.0 * distance));
  return lights::ggxD(g.NoH, alphaPrime);
}

MB_REFERENCE("d_sphere_modification", dSphereModification);
MB_GROUND_TRUTH("d_sphere_modification", lights::sphereEffectiveD);

}  // namespace mb::ref
