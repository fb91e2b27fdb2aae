// Reference for f_schlick_nov: Schlick 1994 eq. 15 with cos theta = n.v (KHR_materials_clearcoat,
// fresnel_coat). Ground truth: the exact dielectric Fresnel at the same angle, with the IOR
// implied by f0 (f90 = 1 only), as for f_schlick.
#include "common/microfacet_reference.hpp"

namespace mb::ref {

static Vec3 fSchlickNoV(Geometry g, Vec3 f0, double f90) {
  double weight = std::pow(1.0 - g.NoV, 5.0);
  return f0 + (splat(f90) - f0) * weight;
}

static Vec3 fSchlickNoVTruth(Geometry g, Vec3 f0, double) { return fresnelDielectricFromF0(g.NoV, f0); }

MB_REFERENCE("f_schlick_nov", fSchlickNoV);
MB_GROUND_TRUTH("f_schlick_nov", fSchlickNoVTruth);

}  // namespace mb::ref
