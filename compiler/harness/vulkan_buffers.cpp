// Buffers and memory for one run(): the choice of a host-visible memory type, the mapped
// input and output buffer of each segment of the chunk plan (inputs copied in at creation),
// and one descriptor set per chunk binding that chunk's sub-ranges. Everything made here
// belongs to the run's RunResources (vulkan_internal.hpp), which releases it.
#include <cstring>

#include "harness/chunk_plan.hpp"
#include "harness/gpu_texture.hpp"
#include "harness/vulkan_check.hpp"
#include "harness/vulkan_internal.hpp"

namespace mb::harness {
namespace {

// Host-visible and coherent, so no flushes or invalidates are needed; cached if possible
// because the host reads every output back.
uint32_t hostMemoryType(const DeviceContext& ctx, uint32_t allowedTypes) {
  const VkMemoryPropertyFlags required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  for (VkMemoryPropertyFlags wanted : {required | VK_MEMORY_PROPERTY_HOST_CACHED_BIT, required}) {
    for (uint32_t i = 0; i < ctx.memory.memoryTypeCount; ++i) {
      if ((allowedTypes & (1u << i)) && (ctx.memory.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
    }
  }
  throw HarnessError("the device has no host-visible, host-coherent memory for storage buffers");
}

}  // namespace

void createMappedBuffer(const DeviceContext& ctx, uint64_t bytes, VkBufferUsageFlags usage, MappedBuffer& b) {
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = bytes;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  MB_VK_CHECK(vkCreateBuffer(ctx.device, &info, nullptr, &b.buffer));

  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(ctx.device, b.buffer, &req);
  VkMemoryAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = hostMemoryType(ctx, req.memoryTypeBits);
  MB_VK_CHECK(vkAllocateMemory(ctx.device, &alloc, nullptr, &b.memory));
  MB_VK_CHECK(vkBindBufferMemory(ctx.device, b.buffer, b.memory, 0));
  MB_VK_CHECK(vkMapMemory(ctx.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped));
}

// One input and one output buffer per segment; inputs are copied in at once.
void createBuffers(const DeviceContext& ctx, const ChunkPlan& plan, const std::vector<float>& inputs, uint32_t inStride,
                   RunResources& res) {
  for (const Segment& seg : plan.segments) {
    MappedBuffer& in = res.inBuffers.emplace_back();
    createMappedBuffer(ctx, seg.inBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, in);
    std::memset(in.mapped, 0, seg.inBytes);  // stride-0 dummy bytes stay defined
    const size_t floats = seg.records * inStride;
    if (floats) {
      std::memcpy(in.mapped, inputs.data() + seg.firstRecord * inStride, floats * sizeof(float));
    }
    createMappedBuffer(ctx, seg.outBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, res.outBuffers.emplace_back());
  }
}

// One descriptor set per chunk: all chunks are recorded into one command buffer, and a set
// must not change while a recorded command still refers to it.
void createDescriptorSets(const DeviceContext& ctx, const Kernel& kernel, const ChunkPlan& plan,
                          const std::vector<const GpuTexture*>& textures, RunResources& res) {
  const auto setCount = static_cast<uint32_t>(plan.chunks.size());
  const auto textureCount = static_cast<uint32_t>(textures.size());
  const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2 * setCount},
                                         {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, textureCount * setCount}};
  VkDescriptorPoolCreateInfo poolInfo{};
  poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  poolInfo.maxSets = setCount;
  poolInfo.poolSizeCount = textureCount ? 2 : 1;
  poolInfo.pPoolSizes = sizes;
  MB_VK_CHECK(vkCreateDescriptorPool(ctx.device, &poolInfo, nullptr, &res.descriptorPool));

  const std::vector<VkDescriptorSetLayout> layouts(setCount, kernel.setLayout);
  VkDescriptorSetAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  alloc.descriptorPool = res.descriptorPool;
  alloc.descriptorSetCount = setCount;
  alloc.pSetLayouts = layouts.data();
  res.sets.resize(setCount);
  MB_VK_CHECK(vkAllocateDescriptorSets(ctx.device, &alloc, res.sets.data()));

  std::vector<VkDescriptorBufferInfo> infos(2 * size_t{setCount});  // sized once: writes point in
  std::vector<VkWriteDescriptorSet> writes(2 * size_t{setCount});
  for (uint32_t i = 0; i < setCount; ++i) {
    const Chunk& c = plan.chunks[i];
    infos[2 * i] = {res.inBuffers[c.segment].buffer, c.inOffset, c.inRange};
    infos[2 * i + 1] = {res.outBuffers[c.segment].buffer, c.outOffset, c.outRange};
    for (uint32_t binding = 0; binding < 2; ++binding) {
      VkWriteDescriptorSet& w = writes[2 * i + binding];
      w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      w.dstSet = res.sets[i];
      w.dstBinding = binding;
      w.descriptorCount = 1;
      w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      w.pBufferInfo = &infos[2 * i + binding];
    }
    for (uint32_t k = 0; k < textureCount; ++k) writes.push_back(textures[k]->descriptorWrite(res.sets[i], 2 + k));
  }
  vkUpdateDescriptorSets(ctx.device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

}  // namespace mb::harness
