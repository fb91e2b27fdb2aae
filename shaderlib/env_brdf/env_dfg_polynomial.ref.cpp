// Reference for env_dfg_polynomial: Narkowicz 2014's coefficients b1..b6, d0..d6 in monomial
// form. Ground truth: the split-sum integral with GGX and exact correlated Smith.
#include <algorithm>

#include "common/ibl_reference.hpp"

namespace mb::ref {

static Vec3 envDfgPolynomial(Vec3 f0, double roughness, double NoV) {
  double x = 1.0 - roughness, y = NoV;
  const double b1 = -0.1688, b2 = 1.895, b3 = 0.9903, b4 = -4.853, b5 = 8.404, b6 = -5.069;
  double bias = clamp01(std::min(b1 * x + b2 * x * x, b3 + b4 * y + b5 * y * y + b6 * y * y * y));
  const double d0 = 0.6045, d1 = 1.699, d2 = -0.5228, d3 = -3.603, d4 = 1.404, d5 = 0.1939, d6 = 2.661;
  double delta = clamp01(d0 + d1 * x + d2 * y + d3 * x * x + d4 * x * y + d5 * y * y + d6 * x * x * x);
  double scale = delta - bias;
  return f0 * scale + splat(bias * clamp01(50.0 * f0.y));
}

static Vec3 envBrdfTruth(Vec3 f0, double roughness, double NoV) { return envBrdfIntegral(f0, roughness, NoV); }

MB_REFERENCE("env_dfg_polynomial", envDfgPolynomial);
MB_GROUND_TRUTH("env_dfg_polynomial", envBrdfTruth);

}  // namespace mb::ref
