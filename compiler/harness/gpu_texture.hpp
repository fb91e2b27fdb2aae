// Sampled RGBA32F textures on the harness's device: a cube image with all its mips (the
// preview's prefiltered environment) or a 2D image (the DFG LUT), each with its view and a
// sampler, uploaded once and left in SHADER_READ_ONLY_OPTIMAL. The preview's graphics
// pipeline binds them as combined image samplers (docs/fragment-stage.md bindings 2 and 3);
// compute kernels can sample them too (VulkanHarness::createKernel with sampled textures).
//
// The sampler is what the fragment stage expects: linear min/mag filtering, linear between
// mips, clamp to edge, no anisotropy, lod range [0, mips - 1]. Seamless cube filtering is
// always on in Vulkan (there is no switch), so a cube is filtered across its face edges.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "harness/vulkan_resources.hpp"

namespace mb::harness {

class VulkanHarness;
struct DeviceContext;

// One mip level: layers x height x width texels of RGBA (4 floats), row-major, layer-major.
struct TextureLevel {
  uint32_t width = 0, height = 0;
  std::vector<float> rgba;
};

class GpuTexture {
 public:
  ~GpuTexture();
  GpuTexture(const GpuTexture&) = delete;
  GpuTexture& operator=(const GpuTexture&) = delete;

  VkImage image() const { return image_.image; }
  VkImageView view() const { return image_.view; }
  VkSampler sampler() const { return sampler_; }
  bool isCube() const { return cube_; }
  uint32_t mipLevels() const { return mips_; }
  // {sampler, view, SHADER_READ_ONLY_OPTIMAL}, for a combined image sampler descriptor.
  const VkDescriptorImageInfo& descriptorInfo() const { return info_; }
  // A write of this texture to `binding` of `set` (COMBINED_IMAGE_SAMPLER, one descriptor);
  // pImageInfo points into this object, so pass it to vkUpdateDescriptorSets while it lives.
  VkWriteDescriptorSet descriptorWrite(VkDescriptorSet set, uint32_t binding) const;

 private:
  friend std::shared_ptr<GpuTexture> uploadTexture(VulkanHarness&, bool, const std::vector<TextureLevel>&);
  explicit GpuTexture(std::shared_ptr<DeviceContext> ctx);
  std::shared_ptr<DeviceContext> ctx_;  // keeps the device alive as long as the texture
  DeviceImage image_;
  VkSampler sampler_ = VK_NULL_HANDLE;
  VkDescriptorImageInfo info_{};
  bool cube_ = false;
  uint32_t mips_ = 0;
};

// Uploads `levels` (level 0 first, each half the size of the one before, down to any size)
// as VK_FORMAT_R32G32B32A32_SFLOAT: a cube (6 layers, square levels) when `cube`, else a 2D
// image (1 layer). Throws HarnessError when the level sizes are inconsistent or the device
// cannot sample and linearly filter RGBA32F.
std::shared_ptr<GpuTexture> uploadTexture(VulkanHarness& gpu, bool cube, const std::vector<TextureLevel>& levels);

}  // namespace mb::harness
