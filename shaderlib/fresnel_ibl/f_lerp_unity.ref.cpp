// Reference for f_lerp_unity: Unity's FresnelLerp(F0, F90, cosA) = lerp(F0, F90, (1 - cosA)^5)
// with F90 = saturate(smoothness + reflectivity) and cosA = n.v.
#include <algorithm>

#include "common/reference.hpp"

namespace mb::ref {

static Vec3 fLerpUnity(Geometry g, Vec3 f0, double perceptualRoughness) {
  double smoothness = 1.0 - perceptualRoughness;
  double reflectivity = std::max({f0.x, f0.y, f0.z});
  double grazingTerm = clamp01(smoothness + reflectivity);
  return mix(f0, splat(grazingTerm), std::pow(clamp01(1.0 - g.NoV), 5.0));
}

MB_REFERENCE("f_lerp_unity", fLerpUnity);

}  // namespace mb::ref
