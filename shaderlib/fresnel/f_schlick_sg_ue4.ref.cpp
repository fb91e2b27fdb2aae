// Reference for f_schlick_sg_ue4: Karis 2013, F = F0 + (1 - F0) 2^((-5.55473 v.h - 6.98316) v.h),
// generalised to f90 in place of 1. Ground truth: exact dielectric Fresnel with the IOR
// implied per channel by f0 (f90 = 1 only), as for f_schlick.
#include "common/microfacet_reference.hpp"

namespace mb::ref {

static Vec3 fSchlickSgUe4(Geometry g, Vec3 f0, double f90) {
  double VoH = g.VoH;
  double weight = std::pow(2.0, (-5.55473 * VoH - 6.98316) * VoH);
  return f0 + (splat(f90) - f0) * weight;
}

static Vec3 fSchlickSgUe4Truth(Geometry g, Vec3 f0, double) { return fresnelDielectricFromF0(g.VoH, f0); }

MB_REFERENCE("f_schlick_sg_ue4", fSchlickSgUe4);
MB_GROUND_TRUTH("f_schlick_sg_ue4", fSchlickSgUe4Truth);

}  // namespace mb::ref
