// Reference for f_schlick: Schlick 1994 eq. 15, F = f0 + (f90 - f0) (1 - cos theta_d)^5 with
// cos theta_d = v.h. Ground truth: exact unpolarized dielectric Fresnel (Born & Wolf) with the
// index of refraction implied per channel by f0, eta = (1 + sqrt f0) / (1 - sqrt f0); it has
// f90 = 1 by construction, so it is the truth for the physical f90 = 1 only (f90 is ignored).
#include "common/microfacet_reference.hpp"

namespace mb::ref {

static Vec3 fSchlick(Geometry g, Vec3 f0, double f90) {
  double weight = std::pow(1.0 - g.VoH, 5.0);
  return f0 + (splat(f90) - f0) * weight;
}

static Vec3 fSchlickTruth(Geometry g, Vec3 f0, double) { return fresnelDielectricFromF0(g.VoH, f0); }

MB_REFERENCE("f_schlick", fSchlick);
MB_GROUND_TRUTH("f_schlick", fSchlickTruth);

}  // namespace mb::ref
