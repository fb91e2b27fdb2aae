// How finely a device's sampler resolves linear filtering (VkPhysicalDeviceLimits, Vulkan spec
// "Limits"): the weights of linear filtering within a level keep `subTexelBits` fraction bits
// ("Texel Linear Filtering": "the number of fraction bits retained is specified by
// subTexelPrecisionBits"), and the fraction between two mip levels keeps `mipmapBits` ("Image
// Level(s) Selection": "quantized to the number of mipmap precision bits"). The spec requires
// at least 4 of each; lavapipe reports 8 and 4 but filters in fp32, an NVIDIA H100 reports 8
// and 8.
#pragma once
#include <cstdint>

namespace mb::harness {

class VulkanHarness;

struct SamplerPrecision {
  uint32_t subTexelBits = 4, mipmapBits = 4;
};

// subTexelPrecisionBits and mipmapPrecisionBits as `gpu`'s device reports them, even below the
// spec's minimum: the bound derived from them (preview/texel_filter.hpp) only widens as they
// shrink, down to 0 bits (any weight in [0, 1]).
SamplerPrecision samplerPrecision(const VulkanHarness& gpu);

}  // namespace mb::harness
