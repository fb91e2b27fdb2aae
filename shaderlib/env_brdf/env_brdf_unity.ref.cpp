// Reference for env_brdf_unity: Unity's EnvironmentBRDFSpecular, surfaceReduction
// 1/(roughness^2 + 1) with roughness = perceptualRoughness^2, times
// lerp(specColor, grazingTerm, Pow4(1 - n.v)). Ground truth: the split-sum integral.
#include <algorithm>

#include "common/ibl_reference.hpp"

namespace mb::ref {

static Vec3 envBrdfUnity(Vec3 f0, double perceptualRoughness, double NoV) {
  double roughness = perceptualRoughness * perceptualRoughness;
  double surfaceReduction = 1.0 / (roughness * roughness + 1.0);
  double grazingTerm = clamp01((1.0 - perceptualRoughness) + std::max({f0.x, f0.y, f0.z}));
  double fresnelTerm = std::pow(clamp01(1.0 - NoV), 4.0);
  return mix(f0, splat(grazingTerm), fresnelTerm) * surfaceReduction;
}

static Vec3 envBrdfTruth(Vec3 f0, double roughness, double NoV) { return envBrdfIntegral(f0, roughness, NoV); }

MB_REFERENCE("env_brdf_unity", envBrdfUnity);
MB_GROUND_TRUTH("env_brdf_unity", envBrdfTruth);

}  // namespace mb::ref
