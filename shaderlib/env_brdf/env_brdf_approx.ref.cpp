// Reference for env_brdf_approx: Karis 2014's fit written out per term,
//   x = 1 - R, a004 = min(x^2, 2^(-9.28 n.v)) x + (0.0425 - 0.0275 R),
//   scale = -1.04 a004 + 1.04 - 0.572 R,  bias = 1.04 a004 - 0.04 + 0.022 R,
//   E = max(f0 scale + bias, 0)  (the fit's bias dips below 0 at high R and n.v, where the
//   integral it fits is positive: the result is clamped, as the brick).
// Ground truth: the split-sum integral Int Gv (f0 + (1 - f0) Fc) with GGX, exact correlated
// Smith and alpha = R^2, by quadrature (common/ibl_reference.hpp).
#include <algorithm>

#include "common/ibl_reference.hpp"

namespace mb::ref {

static Vec3 envBrdfApprox(Vec3 f0, double roughness, double NoV) {
  double x = 1.0 - roughness;
  double a004 = std::min(x * x, std::exp2(-9.28 * NoV)) * x + (0.0425 - 0.0275 * roughness);
  double scale = -1.04 * a004 + (1.04 - 0.572 * roughness);
  double bias = 1.04 * a004 + (-0.04 + 0.022 * roughness);
  Vec3 e = f0 * scale + splat(bias);
  return {std::max(e.x, 0.0), std::max(e.y, 0.0), std::max(e.z, 0.0)};
}

static Vec3 envBrdfTruth(Vec3 f0, double roughness, double NoV) { return envBrdfIntegral(f0, roughness, NoV); }

MB_REFERENCE("env_brdf_approx", envBrdfApprox);
MB_GROUND_TRUTH("env_brdf_approx", envBrdfTruth);

}  // namespace mb::ref
