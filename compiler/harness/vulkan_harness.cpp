// The Vulkan compute harness (see vulkan_harness.hpp for the kernel contract).
//
// This file owns the pipelines and the dispatch: a Kernel's shader module, layouts and
// compute pipeline; per run the timestamp query pool, the one-shot command buffer
// (vulkan_resources.hpp) with every chunk's dispatch, the GPU time from the timestamps and
// the copy of the outputs; and the VulkanHarness methods that tie these to the device
// (vulkan_device.cpp) and the buffers (vulkan_buffers.cpp). The objects they share are in
// vulkan_internal.hpp.
#include "harness/vulkan_harness.hpp"

#include <cstdio>

#include <atomic>
#include <chrono>
#include <cstring>
#include <list>

#include "core/descriptor_bindings.hpp"
#include "harness/chunk_plan.hpp"
#include "harness/vulkan_check.hpp"
#include "harness/vulkan_internal.hpp"

namespace mb::harness {
namespace {

constexpr uint32_t kSpirvMagic = 0x07230203;

void createShaderModule(Kernel& k, const std::vector<uint32_t>& spirv) {
  // Garbage here would reach the driver unchecked when validation is off.
  if (spirv.size() < 5 || spirv[0] != kSpirvMagic)
    throw HarnessError("createKernel: not a SPIR-V module (missing magic number)");
  VkShaderModuleCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  info.codeSize = spirv.size() * sizeof(uint32_t);
  info.pCode = spirv.data();
  MB_VK_CHECK(vkCreateShaderModule(k.ctx->device, &info, nullptr, &k.module));
}

void createLayouts(Kernel& k) {
  static_assert(kKernelInputBinding == 0 && kKernelOutputBinding == 1 && kKernelFirstTextureBinding == 2 &&
                    kKernelTableBinding == 2,
                "the kernel's bindings are numbered consecutively: MbIn, MbOut, then the sampled textures or "
                "the table");
  // The storage buffers, then the textures.
  const uint32_t firstTexture = k.readsTable ? 3 : 2;
  std::vector<VkDescriptorSetLayoutBinding> bindings(firstTexture + k.sampledTextures);
  for (uint32_t i = 0; i < bindings.size(); ++i) {
    bindings[i].binding = i;
    bindings[i].descriptorType =
        i < firstTexture ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    bindings[i].descriptorCount = 1;
    bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  }
  VkDescriptorSetLayoutCreateInfo setInfo{};
  setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  setInfo.bindingCount = static_cast<uint32_t>(bindings.size());
  setInfo.pBindings = bindings.data();
  MB_VK_CHECK(vkCreateDescriptorSetLayout(k.ctx->device, &setInfo, nullptr, &k.setLayout));

  VkPushConstantRange push{};
  push.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  push.offset = 0;
  push.size = sizeof(uint32_t);  // MbPush.count
  VkPipelineLayoutCreateInfo layoutInfo{};
  layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &k.setLayout;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &push;
  MB_VK_CHECK(vkCreatePipelineLayout(k.ctx->device, &layoutInfo, nullptr, &k.pipelineLayout));
}

void createPipeline(Kernel& k) {
  VkComputePipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = k.module;
  info.stage.pName = "main";
  info.layout = k.pipelineLayout;
  MB_VK_CHECK(vkCreateComputePipelines(k.ctx->device, VK_NULL_HANDLE, 1, &info, nullptr, &k.pipeline));
}

void createQueryPool(const DeviceContext& ctx, uint32_t chunkCount, RunResources& res) {
  if (ctx.timestampValidBits == 0) return;  // run() falls back to wall time
  VkQueryPoolCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = 2 * chunkCount;
  MB_VK_CHECK(vkCreateQueryPool(ctx.device, &info, nullptr, &res.queryPool));
}

// All chunks in one command buffer. Chunks touch disjoint ranges, so no barriers between
// dispatches; one barrier at the end makes the shader writes visible to the host.
void recordCommands(const Kernel& kernel, const ChunkPlan& plan, RunResources& res) {
  const VkCommandBuffer cmd = res.commands->cmd();
  const auto chunkCount = static_cast<uint32_t>(plan.chunks.size());
  if (res.queryPool) vkCmdResetQueryPool(cmd, res.queryPool, 0, 2 * chunkCount);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernel.pipeline);
  for (uint32_t i = 0; i < chunkCount; ++i) {
    const uint32_t count = plan.chunks[i].records;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernel.pipelineLayout, 0, 1, &res.sets[i], 0, nullptr);
    vkCmdPushConstants(cmd, kernel.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(count), &count);
    // Both stamps at the compute stage: the first waits for the previous chunk's shaders,
    // so chunk intervals do not overlap and their sum does not count time twice.
    if (res.queryPool) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, res.queryPool, 2 * i);
    vkCmdDispatch(cmd, (count + kLocalSizeX - 1) / kLocalSizeX, 1, 1);
    if (res.queryPool) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, res.queryPool, 2 * i + 1);
  }
  VkMemoryBarrier toHost{};
  toHost.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr,
                       0, nullptr);
}

// Runs at least this long (host, submit to fence) are checked against their timestamps.
constexpr double kTimestampCheckMinWallMs = 20.0;

// Sum over chunks of (end - begin) ticks, converted with timestampPeriod (ns per tick).
double timestampMs(const DeviceContext& ctx, uint32_t chunkCount, const RunResources& res) {
  std::vector<uint64_t> stamps(2 * size_t{chunkCount});
  MB_VK_CHECK(vkGetQueryPoolResults(ctx.device, res.queryPool, 0, 2 * chunkCount, stamps.size() * sizeof(uint64_t),
                                    stamps.data(), sizeof(uint64_t),
                                    VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  // Only the low timestampValidBits bits count; masking the difference handles wrap-around.
  const uint64_t mask = ctx.timestampValidBits >= 64 ? ~uint64_t{0} : (uint64_t{1} << ctx.timestampValidBits) - 1;
  double ns = 0;
  for (uint32_t i = 0; i < chunkCount; ++i) {
    const uint64_t ticks = (stamps[2 * i + 1] - stamps[2 * i]) & mask;
    ns += static_cast<double>(ticks) * ctx.props.limits.timestampPeriod;
  }
  return ns / 1e6;
}

void copyOutputs(const ChunkPlan& plan, uint32_t outStride, const RunResources& res, std::vector<float>& outputs) {
  for (size_t s = 0; s < plan.segments.size(); ++s) {
    const Segment& seg = plan.segments[s];
    const size_t floats = seg.records * outStride;
    if (floats == 0) continue;
    std::memcpy(outputs.data() + seg.firstRecord * outStride, res.outBuffers[s].mapped, floats * sizeof(float));
  }
}

}  // namespace

struct VulkanHarness::Impl {
  std::shared_ptr<DeviceContext> ctx;
  DeviceOptions options;
  // kernelFor's cache: SPIR-V bytes -> kernel, most recently used first.
  std::mutex kernelMutex;
  std::list<std::pair<std::string, std::shared_ptr<Kernel>>> kernels;
  // Cleared when a run's timestamps missed its work (runOnce); then every run is timed by the host.
  std::atomic<bool> timestampsTrusted{true};

  RunResult runOnce(Kernel& kernel, const std::vector<float>& inputs, uint32_t inStride, uint32_t outStride,
                    uint64_t count, const std::vector<const GpuTexture*>& textures, const std::vector<float>* table);
};

VulkanHarness::VulkanHarness(const DeviceOptions& options) : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
  // Filled step by step: if a step throws, ~DeviceContext releases what was made so far.
  impl_->ctx = std::make_shared<DeviceContext>();
  createInstance(*impl_->ctx, options.validation);
  createDevice(*impl_->ctx, options);
}

VulkanHarness::~VulkanHarness() = default;

std::string VulkanHarness::deviceName() const { return impl_->ctx->props.deviceName; }

std::string VulkanHarness::deviceIdentity() const {
  const VkPhysicalDeviceProperties& p = impl_->ctx->props;
  char ids[64];
  std::snprintf(ids, sizeof ids, "%08x:%08x:%08x:%08x:", p.vendorID, p.deviceID, p.driverVersion, p.apiVersion);
  std::string uuid;
  for (uint8_t b : p.pipelineCacheUUID) {
    char hex[3];
    std::snprintf(hex, sizeof hex, "%02x", b);
    uuid += hex;
  }
  return ids + uuid + ":" + p.deviceName;
}

bool VulkanHarness::isLavapipe() const { return isLavapipeName(deviceName()); }

uint32_t VulkanHarness::maxWorkGroupCountX() const { return impl_->ctx->props.limits.maxComputeWorkGroupCount[0]; }

uint64_t VulkanHarness::maxStorageBufferRange() const { return impl_->ctx->props.limits.maxStorageBufferRange; }

double VulkanHarness::timestampPeriodNs() const { return impl_->ctx->props.limits.timestampPeriod; }

bool VulkanHarness::supportsShaderFloat16() const { return impl_->ctx->shaderFloat16; }

std::shared_ptr<DeviceContext> VulkanHarness::context() const { return impl_->ctx; }

std::shared_ptr<Kernel> VulkanHarness::createKernel(const std::vector<uint32_t>& spirv, uint32_t sampledTextures,
                                                    bool readsTable) {
  if (sampledTextures && readsTable) throw HarnessError("createKernel: a kernel samples textures or reads a table");
  auto kernel = std::make_shared<Kernel>(impl_->ctx);
  kernel->sampledTextures = sampledTextures;
  kernel->readsTable = readsTable;
  createShaderModule(*kernel, spirv);
  createLayouts(*kernel);
  createPipeline(*kernel);
  return kernel;
}

RunResult VulkanHarness::Impl::runOnce(Kernel& kernel, const std::vector<float>& inputs, uint32_t inStride,
                                       uint32_t outStride, uint64_t count,
                                       const std::vector<const GpuTexture*>& textures,
                                       const std::vector<float>* table) {
  const DeviceContext& ctx = *this->ctx;
  RunResult result;
  ChunkLimits limits;
  limits.maxGroupsX = ctx.props.limits.maxComputeWorkGroupCount[0];
  limits.maxRangeBytes = ctx.props.limits.maxStorageBufferRange;
  limits.offsetAlignment = ctx.props.limits.minStorageBufferOffsetAlignment;
  limits.maxSegmentBytes = ctx.maxSegmentBytes;
  limits.recordCap = options.maxRecordsPerChunk;
  const ChunkPlan plan = planChunks(count, inStride, outStride, limits);
  const auto chunkCount = static_cast<uint32_t>(plan.chunks.size());

  RunResources res(ctx);
  createBuffers(ctx, plan, inputs, inStride, res);
  if (table) createTableBuffer(ctx, *table, res);
  createDescriptorSets(ctx, kernel, plan, textures, res);
  createQueryPool(ctx, chunkCount, res);
  res.commands.emplace(ctx);
  recordCommands(kernel, plan, res);
  const double wallMs = res.commands->submitAndWait("the kernel");

  result.chunks = chunkCount;
  result.gpuTimestamps = res.queryPool != VK_NULL_HANDLE && timestampsTrusted;
  result.gpuMs = result.gpuTimestamps ? timestampMs(ctx, chunkCount, res) : wallMs;
  // The GPU interval lies inside the host's submit-to-fence interval, and for a long dispatch it
  // is most of it. Lavapipe (Mesa 22.3) stops stamping compute work once the process has drawn
  // with a graphics pipeline (a preview): a 1.0 s dispatch read 0.07 ms, and bench's calibration
  // scaled its dispatches up 10,000-fold from it (measured in `report`, which renders previews
  // before it times permutations). From the first such run on, this harness times by the host.
  if (result.gpuTimestamps && wallMs > kTimestampCheckMinWallMs && result.gpuMs < 0.1 * wallMs) {
    timestampsTrusted = false;
    result.gpuTimestamps = false;
    result.gpuMs = wallMs;
  }
  result.outputs.resize(count * outStride);
  copyOutputs(plan, outStride, res, result.outputs);
  return result;
}

std::shared_ptr<Kernel> VulkanHarness::kernelFor(const std::vector<uint32_t>& spirv, bool readsTable) {
  std::string bytes(reinterpret_cast<const char*>(spirv.data()), spirv.size() * sizeof(uint32_t));
  bytes += readsTable ? 'T' : '-';  // the same module with another layout is another kernel
  {
    std::lock_guard lock(impl_->kernelMutex);
    auto& list = impl_->kernels;
    for (auto it = list.begin(); it != list.end(); ++it) {
      if (it->first == bytes) {
        list.splice(list.begin(), list, it);  // most recently used first
        return list.front().second;
      }
    }
  }
  // Created outside the lock: two threads asking for the same new SPIR-V both create one,
  // and the cache keeps the later; both kernels are valid.
  auto kernel = createKernel(spirv, 0, readsTable);
  std::lock_guard lock(impl_->kernelMutex);
  impl_->kernels.emplace_front(std::move(bytes), kernel);
  if (impl_->kernels.size() > kKernelCacheSize) impl_->kernels.pop_back();
  return kernel;
}

RunResult VulkanHarness::run(Kernel& kernel, const std::vector<float>& inputs, uint32_t inStride, uint32_t outStride,
                             uint64_t count) {
  return run(kernel, inputs, inStride, outStride, count, {}, nullptr);
}

RunResult VulkanHarness::run(Kernel& kernel, const std::vector<float>& inputs, uint32_t inStride, uint32_t outStride,
                             uint64_t count, const std::vector<const GpuTexture*>& textures,
                             const std::vector<float>* table) {
  const DeviceContext& ctx = *impl_->ctx;
  if (kernel.ctx.get() != &ctx) throw HarnessError("run: the kernel belongs to another harness");
  if (textures.size() != kernel.sampledTextures) {
    throw HarnessError("run: the kernel samples " + std::to_string(kernel.sampledTextures) + " textures, got " +
                       std::to_string(textures.size()));
  }
  if (kernel.readsTable != (table != nullptr))
    throw HarnessError(kernel.readsTable ? "run: the kernel reads a table, none given"
                                         : "run: a table given to a kernel that reads none");
  if (inputs.size() != count * inStride) {
    throw HarnessError("run: expected " + std::to_string(count) + " records x " + std::to_string(inStride) +
                       " floats = " + std::to_string(count * inStride) + " inputs, got " +
                       std::to_string(inputs.size()));
  }
  RunResult result;
  if (count == 0) return result;

  double firstDispatchMs = 0;
  if (impl_->options.warmUpFirstDispatch && !kernel.warmedUp.load()) {
    std::lock_guard lock(kernel.warmUpMutex);
    if (impl_->options.warmUpFirstDispatch && !kernel.warmedUp.load()) {
      // One record of the real inputs: the JIT happens here, outside the timed dispatches.
      const std::vector<float> first(inputs.begin(), inputs.begin() + inStride);
      const auto t0 = std::chrono::steady_clock::now();
      impl_->runOnce(kernel, first, inStride, outStride, 1, textures, table);
      firstDispatchMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      kernel.warmedUp.store(true);
    }
  }
  result = impl_->runOnce(kernel, inputs, inStride, outStride, count, textures, table);
  result.firstDispatchMs = firstDispatchMs;
  return result;
}

std::vector<std::string> VulkanHarness::validationMessages() const { return impl_->ctx->log.snapshot(); }

void VulkanHarness::clearValidationMessages() { impl_->ctx->log.clear(); }

}  // namespace mb::harness
