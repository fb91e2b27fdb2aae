// Reference for f_lerp_fast_unity: Unity's FresnelLerpFast(F0, F90, cosA) = lerp(F0, F90,
// (1 - cosA)^4), F90 = saturate(smoothness + reflectivity), cosA = n.v.
#include <algorithm>

#include "common/reference.hpp"

namespace mb::ref {

static Vec3 fLerpFastUnity(Geometry g, Vec3 f0, double perceptualRoughness) {
  double grazingTerm = clamp01((1.0 - perceptualRoughness) + std::max({f0.x, f0.y, f0.z}));
  return mix(f0, splat(grazingTerm), std::pow(clamp01(1.0 - g.NoV), 4.0));
}

MB_REFERENCE("f_lerp_fast_unity", fLerpFastUnity);

}  // namespace mb::ref
