// RGBA32F textures on the harness's device (gpu_texture.hpp): the image in device memory,
// filled from one staging buffer by one copy per mip level, moved to
// SHADER_READ_ONLY_OPTIMAL by barriers in the same command buffer, then its view and sampler.
#include "harness/gpu_texture.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "harness/vulkan_check.hpp"
#include "harness/vulkan_internal.hpp"

namespace mb::harness {
namespace {

constexpr VkFormat kFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

void checkLevels(bool cube, const std::vector<TextureLevel>& levels) {
  if (levels.empty()) throw HarnessError("uploadTexture: no mip levels");
  const uint32_t layers = cube ? 6 : 1;
  for (size_t i = 0; i < levels.size(); ++i) {
    const TextureLevel& l = levels[i];
    const uint32_t w = std::max(1u, levels[0].width >> i), h = std::max(1u, levels[0].height >> i);
    const bool sizeOk = l.width == w && l.height == h && (!cube || w == h) && w > 0 && h > 0;
    if (!sizeOk || l.rgba.size() != size_t{layers} * w * h * 4) {
      throw HarnessError("uploadTexture: level " + std::to_string(i) + " is " + std::to_string(l.width) + "x" +
                         std::to_string(l.height) + " with " + std::to_string(l.rgba.size()) + " floats, expected " +
                         std::to_string(w) + "x" + std::to_string(h) + " x " + std::to_string(layers) + " layers x 4");
    }
  }
}

void requireLinearFiltering(const DeviceContext& ctx) {
  VkFormatProperties props{};
  vkGetPhysicalDeviceFormatProperties(ctx.physical, kFormat, &props);
  const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT |
                                      VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  if ((props.optimalTilingFeatures & needed) != needed)
    throw HarnessError("the device cannot sample and linearly filter R32G32B32A32_SFLOAT images");
}

void imageBarrier(VkCommandBuffer cmd, VkImage image, uint32_t mips, uint32_t layers, VkImageLayout from,
                  VkImageLayout to, VkAccessFlags srcAccess, VkAccessFlags dstAccess, VkPipelineStageFlags srcStage,
                  VkPipelineStageFlags dstStage) {
  VkImageMemoryBarrier b{};
  b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
  b.srcAccessMask = srcAccess;
  b.dstAccessMask = dstAccess;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, mips, 0, layers};
  vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

}  // namespace

GpuTexture::GpuTexture(std::shared_ptr<DeviceContext> ctx) : ctx_(std::move(ctx)) {}

GpuTexture::~GpuTexture() {
  if (sampler_) vkDestroySampler(ctx_->device, sampler_, nullptr);
}  // then the image, before ctx_

VkWriteDescriptorSet GpuTexture::descriptorWrite(VkDescriptorSet set, uint32_t binding) const {
  VkWriteDescriptorSet w{};
  w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
  w.dstSet = set;
  w.dstBinding = binding;
  w.descriptorCount = 1;
  w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  w.pImageInfo = &info_;
  return w;
}

std::shared_ptr<GpuTexture> uploadTexture(VulkanHarness& gpu, bool cube, const std::vector<TextureLevel>& levels) {
  checkLevels(cube, levels);
  const std::shared_ptr<DeviceContext> ctx = gpu.context();
  requireLinearFiltering(*ctx);
  std::shared_ptr<GpuTexture> t(new GpuTexture(ctx));
  const uint32_t layers = cube ? 6 : 1, mips = static_cast<uint32_t>(levels.size());
  t->cube_ = cube;
  t->mips_ = mips;

  VkImageCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  info.flags = cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = kFormat;
  info.extent = {levels[0].width, levels[0].height, 1};
  info.mipLevels = mips;
  info.arrayLayers = layers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  t->image_.create(*ctx, info, cube ? VK_IMAGE_VIEW_TYPE_CUBE : VK_IMAGE_VIEW_TYPE_2D, VK_IMAGE_ASPECT_COLOR_BIT);
  const VkImage image = t->image_.image;

  // One staging buffer with every level back to back; each level's layers are consecutive
  // width x height slices, which is what vkCmdCopyBufferToImage reads for a layer range.
  uint64_t total = 0;
  std::vector<VkBufferImageCopy> copies;
  for (uint32_t i = 0; i < mips; ++i) {
    VkBufferImageCopy c{};
    c.bufferOffset = total;
    c.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, i, 0, layers};
    c.imageExtent = {levels[i].width, levels[i].height, 1};
    copies.push_back(c);
    total += levels[i].rgba.size() * sizeof(float);
  }
  MappedBuffer staging;
  staging.create(*ctx, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  for (uint32_t i = 0; i < mips; ++i)
    std::memcpy(static_cast<char*>(staging.mapped) + copies[i].bufferOffset, levels[i].rgba.data(),
                levels[i].rgba.size() * sizeof(float));

  {
    // Released before the staging buffer, which the copy reads until it has finished.
    OneShotCommands commands(*ctx);
    const VkCommandBuffer cmd = commands.cmd();
    imageBarrier(cmd, image, mips, layers, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                 VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    vkCmdCopyBufferToImage(cmd, staging.buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           static_cast<uint32_t>(copies.size()), copies.data());
    // Readable by any shader stage afterwards: the preview's fragment shader and compute kernels.
    imageBarrier(cmd, image, mips, layers, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT);
    commands.submitAndWait("the texture upload");
  }

  VkSamplerCreateInfo s{};
  s.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
  s.magFilter = VK_FILTER_LINEAR;
  s.minFilter = VK_FILTER_LINEAR;
  s.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  s.addressModeU = s.addressModeV = s.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  s.anisotropyEnable = VK_FALSE;
  s.compareEnable = VK_FALSE;
  s.minLod = 0.0f;
  s.maxLod = static_cast<float>(mips - 1);
  s.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
  MB_VK_CHECK(vkCreateSampler(ctx->device, &s, nullptr, &t->sampler_));
  t->info_ = {t->sampler_, t->image_.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  return t;
}

}  // namespace mb::harness
