// The preview's environment inputs as GPU textures (docs/fragment-stage.md): the prefiltered
// cube at binding 2 (samplerCube mbPrefilteredEnv) and the DFG LUT at binding 3 (sampler2D
// mbDfgLut, u = NoV, v = perceptual roughness), with the samplers of harness/gpu_texture.hpp.
#pragma once
#include <memory>

#include "harness/gpu_texture.hpp"
#include "lut/dfg_lut.hpp"
#include "ltc/ltc_table.hpp"
#include "validate/probe_ltc_table.hpp"
#include "preview/environment.hpp"

namespace mb::preview {

inline constexpr uint32_t kPrefilteredEnvBinding = 2;
inline constexpr uint32_t kDfgLutBinding = 3;

// Every level of `env` as a cube image with mips.
std::shared_ptr<harness::GpuTexture> uploadEnvironmentCube(harness::VulkanHarness& gpu, const EnvironmentMaps& env);

// The LUT as a size x size 2D image, one level; its three channels in r, g, b (lut/dfg_lut.hpp
// order, row 0 = smoothest at t = 0) and a = 1.
std::shared_ptr<harness::GpuTexture> uploadDfgLut(harness::VulkanHarness& gpu, const lut::LutTable& table);
// Its texels as uploaded (RGBA32F, row-major), for the APIs that take CPU data (draw_passes.cpp).
std::vector<float> dfgLutTexels(const lut::LutTable& table);

// The LTC tables as the fragment stage reads them (docs/fragment-stage.md "LTC table"): 4 size x
// size texels, the specular table's entry (i, j) at texel (j, i) as (m00, m02, m20, m22) and at
// (size + j, i) as (norm, fresnel, 0, 0), the sheen's at (2 size + j, i) and (3 size + j, i).
std::shared_ptr<harness::GpuTexture> uploadLtcTable(harness::VulkanHarness& gpu, const ProbeLtcTable& tables);

}  // namespace mb::preview
