// Reference for env_brdf_approx_nonmetal: Karis 2014, E = min((1-R)^2, 2^(-9.28 n.v)) (1-R)
// + 0.0425 - 0.0275 R. Ground truth: the split-sum integral at f0 = 0.04 (the brick's
// assumption), whatever f0 is passed.
#include <algorithm>

#include "common/ibl_reference.hpp"

namespace mb::ref {

static Vec3 envBrdfApproxNonmetal(Vec3, double roughness, double NoV) {
  double x = 1.0 - roughness;
  return splat(std::min(x * x, std::exp2(-9.28 * NoV)) * x + 0.0425 - 0.0275 * roughness);
}

static Vec3 envBrdfNonmetalTruth(Vec3, double roughness, double NoV) {
  return envBrdfIntegral(splat(0.04), roughness, NoV);
}

MB_REFERENCE("env_brdf_approx_nonmetal", envBrdfApproxNonmetal);
MB_GROUND_TRUTH("env_brdf_approx_nonmetal", envBrdfNonmetalTruth);

}  // namespace mb::ref
