// Prefiltering an environment on the GPU (docs/environments.md "Prefiltering"): one compute
// kernel per environment, emitted from the Hammersley and GGX importance-sampling bricks and
// the environment's GLSL radiance, run on the harness with one record per texel of every
// level. Karis 2013 PrefilterEnvMap (seed 002): n = v = r = the texel's direction, half
// vectors h drawn from D(h)(n.h) by the brick, l = 2 (v.h) h - v, and the texel is
//   sum_k L(l_k) (n.l_k) / sum_k (n.l_k)   over the samples with n.l_k > 0,
// with the *analytic* radiance L evaluated at l_k (no texture read, so no aliasing of a
// lower level feeds into the next). A peak (the sky's sun, environmentPeak) is left out of that
// sum and integrated over its own cone instead, uniformly in solid angle with the density
// D(h)/4 of l written out, then added to the numerator: 4000:1 over 1e-3 sr is hit by a
// handful of lobe samples, or none. Level 0 is L at the texel centre.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "preview/environment.hpp"

namespace mb {
class ShaderLibrary;
}

namespace mb::preview {

// Hammersley points per texel of the prefiltered levels: 4x Karis's 1024, because the studio's
// box edges left up to 11 % (mean 1.5 %) relative noise at 1024 (docs/environments.md).
inline constexpr uint32_t kPrefilterSamples = 4096;

// Points per texel on the cone of an environment's peak (environment_radiance.hpp PeakCone):
// a quarter of `samples`.
uint32_t peakSamples(uint32_t samples);

// Perceptual roughness level `level` of a chain with `maxMip` + 1 levels is prefiltered at:
// level / maxMip, the inverse of the linear mip_mapping brick.
double levelRoughness(uint32_t level, uint32_t maxMip);

// The kernel's GLSL (harness kernel contract; record = direction xyz, alpha; output rgb).
// Throws DiagnosticError when the library lacks a brick it needs.
std::string prefilterKernelGlsl(const ShaderLibrary& lib, const std::string& name, uint32_t samples);

// The records of every texel of every level of a baseSize cube, level by level, each level's
// texels in CubeLevel order: (x, y, z) of the unit texel direction and alpha = roughness^2
// (0 for level 0), as the fp32 values the kernel reads.
std::vector<float> prefilterRecords(uint32_t baseSize);

// Compiles and runs the kernel; returns the levels (A = 1).
std::vector<CubeLevel> prefilterOnGpu(harness::VulkanHarness& gpu, const std::string& glsl, const std::string& name,
                                      uint32_t baseSize);

}  // namespace mb::preview
