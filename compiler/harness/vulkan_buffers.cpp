// Buffers for one run(): the mapped input and output buffer (vulkan_resources.hpp) of each
// segment of the chunk plan (inputs copied in at creation), and one descriptor set per chunk
// binding that chunk's sub-ranges. Everything made here belongs to the run's RunResources
// (vulkan_internal.hpp), which releases it.
#include <algorithm>
#include <cstring>

#include "core/descriptor_bindings.hpp"
#include "harness/chunk_plan.hpp"
#include "harness/gpu_texture.hpp"
#include "harness/vulkan_check.hpp"
#include "harness/vulkan_internal.hpp"

namespace mb::harness {

// One input and one output buffer per segment; inputs are copied in at once.
void createBuffers(const DeviceContext& ctx, const ChunkPlan& plan, const std::vector<float>& inputs, uint32_t inStride,
                   RunResources& res) {
  for (const Segment& seg : plan.segments) {
    MappedBuffer& in = res.inBuffers.emplace_back();
    in.create(ctx, seg.inBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::memset(in.mapped, 0, seg.inBytes);  // stride-0 dummy bytes stay defined
    const size_t floats = seg.records * inStride;
    if (floats) {
      std::memcpy(in.mapped, inputs.data() + seg.firstRecord * inStride, floats * sizeof(float));
    }
    res.outBuffers.emplace_back().create(ctx, seg.outBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  }
}

void createTableBuffer(const DeviceContext& ctx, const std::vector<float>& table, RunResources& res) {
  const uint64_t bytes = std::max<uint64_t>(1, table.size()) * sizeof(float);
  MappedBuffer& b = res.table.emplace();
  b.create(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  std::memset(b.mapped, 0, bytes);
  if (!table.empty()) std::memcpy(b.mapped, table.data(), table.size() * sizeof(float));
}

// One descriptor set per chunk: all chunks are recorded into one command buffer, and a set
// must not change while a recorded command still refers to it.
void createDescriptorSets(const DeviceContext& ctx, const Kernel& kernel, const ChunkPlan& plan,
                          const std::vector<const GpuTexture*>& textures, RunResources& res) {
  const auto setCount = static_cast<uint32_t>(plan.chunks.size());
  const auto textureCount = static_cast<uint32_t>(textures.size());
  const uint32_t buffersPerSet = res.table ? 3 : 2;
  const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffersPerSet * setCount},
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
  const VkDescriptorBufferInfo tableInfo{res.table ? res.table->buffer : VK_NULL_HANDLE, 0, VK_WHOLE_SIZE};
  for (uint32_t i = 0; i < setCount; ++i) {
    const Chunk& c = plan.chunks[i];
    infos[2 * i] = {res.inBuffers[c.segment].buffer, c.inOffset, c.inRange};
    infos[2 * i + 1] = {res.outBuffers[c.segment].buffer, c.outOffset, c.outRange};
    for (uint32_t j = 0; j < 2; ++j) {
      VkWriteDescriptorSet& w = writes[2 * i + j];
      w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      w.dstSet = res.sets[i];
      w.dstBinding = j == 0 ? kKernelInputBinding : kKernelOutputBinding;
      w.descriptorCount = 1;
      w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      w.pBufferInfo = &infos[2 * i + j];
    }
    if (res.table) {
      VkWriteDescriptorSet& w = writes.emplace_back();
      w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      w.dstSet = res.sets[i];
      w.dstBinding = kKernelTableBinding;
      w.descriptorCount = 1;
      w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      w.pBufferInfo = &tableInfo;
    }
    for (uint32_t k = 0; k < textureCount; ++k)
      writes.push_back(textures[k]->descriptorWrite(res.sets[i], kKernelFirstTextureBinding + k));
  }
  vkUpdateDescriptorSets(ctx.device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

}  // namespace mb::harness
