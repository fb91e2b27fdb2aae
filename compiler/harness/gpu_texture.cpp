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
constexpr uint32_t kTexelBytes = 16;

// Device-local where the device has it (a discrete GPU), else any type the image allows
// (lavapipe's one heap is both).
uint32_t imageMemoryType(const DeviceContext& ctx, uint32_t allowedTypes) {
  for (VkMemoryPropertyFlags wanted :
       {VkMemoryPropertyFlags{VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT}, VkMemoryPropertyFlags{0}}) {
    for (uint32_t i = 0; i < ctx.memory.memoryTypeCount; ++i)
      if ((allowedTypes & (1u << i)) && (ctx.memory.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
  }
  throw HarnessError("the device has no memory type for a sampled image");
}

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
  VkDevice device = ctx_->device;
  if (sampler_) vkDestroySampler(device, sampler_, nullptr);
  if (view_) vkDestroyImageView(device, view_, nullptr);
  if (image_) vkDestroyImage(device, image_, nullptr);
  if (memory_) vkFreeMemory(device, memory_, nullptr);
}

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
  MB_VK_CHECK(vkCreateImage(ctx->device, &info, nullptr, &t->image_));
  VkMemoryRequirements req{};
  vkGetImageMemoryRequirements(ctx->device, t->image_, &req);
  VkMemoryAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = imageMemoryType(*ctx, req.memoryTypeBits);
  MB_VK_CHECK(vkAllocateMemory(ctx->device, &alloc, nullptr, &t->memory_));
  MB_VK_CHECK(vkBindImageMemory(ctx->device, t->image_, t->memory_, 0));

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
  RunResources res(*ctx);
  MappedBuffer& staging = res.inBuffers.emplace_back();
  createMappedBuffer(*ctx, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, staging);
  for (uint32_t i = 0; i < mips; ++i)
    std::memcpy(static_cast<char*>(staging.mapped) + copies[i].bufferOffset, levels[i].rgba.data(),
                levels[i].rgba.size() * sizeof(float));

  allocateCommandBuffer(*ctx, res);
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  MB_VK_CHECK(vkBeginCommandBuffer(res.cmd, &begin));
  imageBarrier(res.cmd, t->image_, mips, layers, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
               VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  vkCmdCopyBufferToImage(res.cmd, staging.buffer, t->image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         static_cast<uint32_t>(copies.size()), copies.data());
  // Readable by any shader stage afterwards: the preview's fragment shader and compute kernels.
  imageBarrier(res.cmd, t->image_, mips, layers, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT);
  MB_VK_CHECK(vkEndCommandBuffer(res.cmd));
  submitAndWait(*ctx, res);

  VkImageViewCreateInfo viewInfo{};
  viewInfo.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
  viewInfo.image = t->image_;
  viewInfo.viewType = cube ? VK_IMAGE_VIEW_TYPE_CUBE : VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = kFormat;
  viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, mips, 0, layers};
  MB_VK_CHECK(vkCreateImageView(ctx->device, &viewInfo, nullptr, &t->view_));

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
  t->info_ = {t->sampler_, t->view_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  return t;
}

}  // namespace mb::harness
