// Reference for env_dfg_lazarov: Narkowicz 2014's EnvDFGLazarov coefficients, evaluated term
// by term with gloss = 1 - roughness. The saturate(50 f0.g) factor fades the bias out for
// f0 < 0.02 ("anything less than 2% is physically impossible", Karis 2013 / Schuler).
// Ground truth: the split-sum integral with GGX and exact correlated Smith.
#include <algorithm>

#include "common/ibl_reference.hpp"

namespace mb::ref {

static Vec3 envDfgLazarov(Vec3 f0, double roughness, double NoV) {
  double gloss = 1.0 - roughness;
  double tx = 0.5745 * gloss + 0.5753, ty = 1.548 * gloss - 0.2511;
  double tz = -0.02397 * gloss - 0.02066, tw = 1.301 * gloss + 0.4755;
  double bias = clamp01(tx * std::min(ty, std::exp2(-7.672 * NoV)) + tz);
  double delta = clamp01(tw);
  double scale = delta - bias;
  double fade = clamp01(50.0 * f0.y);
  return f0 * scale + splat(bias * fade);
}

static Vec3 envBrdfTruth(Vec3 f0, double roughness, double NoV) { return envBrdfIntegral(f0, roughness, NoV); }

MB_REFERENCE("env_dfg_lazarov", envDfgLazarov);
MB_GROUND_TRUTH("env_dfg_lazarov", envBrdfTruth);

}  // namespace mb::ref
