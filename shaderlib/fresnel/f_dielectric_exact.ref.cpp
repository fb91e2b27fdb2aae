// Reference for f_dielectric_exact: the unpolarized Fresnel equations (Born & Wolf) in
// pbrt-v4's FrDielectric form, with eta = (1 + sqrt f0)/(1 - sqrt f0) per channel
// (common/microfacet_reference.hpp). Exact, so also its own ground truth.
#include "common/microfacet_reference.hpp"

namespace mb::ref {

static Vec3 fDielectricExact(Geometry g, Vec3 f0, double) { return fresnelDielectricFromF0(g.VoH, f0); }

MB_REFERENCE("f_dielectric_exact", fDielectricExact);
MB_GROUND_TRUTH("f_dielectric_exact", fDielectricExact);

}  // namespace mb::ref
