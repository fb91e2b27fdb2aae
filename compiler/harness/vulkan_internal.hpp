// Internal to compiler/harness: the objects the harness's files share, and the steps one
// file performs for another. vulkan_device.cpp makes the instance and the device,
// vulkan_resources.cpp the buffers, images and one-shot command buffers of every path,
// vulkan_buffers.cpp a run's buffers and descriptor sets, vulkan_harness.cpp the pipelines,
// the dispatch and the VulkanHarness methods. Not part of the harness's interface:
// everything else includes vulkan_harness.hpp.
//
// Ownership: a DeviceContext owns the instance, the debug messenger and the device. The
// harness and every Kernel hold it through a shared_ptr, so a kernel that outlives its
// harness still destroys its pipeline before the device goes away. Everything a single
// run() creates lives in a RunResources object that releases it on every exit path.
#pragma once
#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "harness/vulkan_harness.hpp"
#include "harness/vulkan_resources.hpp"

namespace mb::harness {

struct ChunkPlan;

// Keeps each buffer allocation modest even where maxMemoryAllocationSize is huge: host-
// visible heaps are often small on discrete GPUs, and a run rarely needs more.
inline constexpr uint64_t kMaxSegmentBytes = uint64_t{256} << 20;

// Validation messages, appended from whatever thread the layer reports on.
class MessageLog {
 public:
  void add(std::string message) {
    std::lock_guard lock(mutex_);
    messages_.push_back(std::move(message));
  }
  std::vector<std::string> snapshot() const {
    std::lock_guard lock(mutex_);
    return messages_;
  }
  void clear() {
    std::lock_guard lock(mutex_);
    messages_.clear();
  }

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> messages_;
};

// Instance, messenger and device, shared by the harness and its kernels.
struct DeviceContext {
  // First member, so destroyed last: vkDestroyInstance still reports into it.
  MessageLog log;
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  PFN_vkDestroyDebugUtilsMessengerEXT destroyMessenger = nullptr;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties props{};
  VkPhysicalDeviceMemoryProperties memory{};
  uint64_t maxSegmentBytes = kMaxSegmentBytes;
  uint32_t queueFamily = 0;
  uint32_t timestampValidBits = 0;
  bool shaderFloat16 = false;  // enabled at device creation (fp16 probes need it)
  bool graphics = false;       // the queue also takes draws (vulkan_graphics.hpp)
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  // vkQueueSubmit and vkDeviceWaitIdle need the queue externally synchronized; everything
  // else a run() creates is its own, so this lock makes concurrent run() calls safe.
  mutable std::mutex queueMutex;

  DeviceContext() = default;
  DeviceContext(const DeviceContext&) = delete;
  DeviceContext& operator=(const DeviceContext&) = delete;
  // Also runs after a constructor step failed, so every handle may still be null.
  ~DeviceContext() {
    if (device) {
      vkDeviceWaitIdle(device);
      vkDestroyDevice(device, nullptr);
    }
    if (messenger && destroyMessenger) destroyMessenger(instance, messenger, nullptr);
    if (instance) vkDestroyInstance(instance, nullptr);
  }
};

// A compute pipeline for one kernel, with the fixed layout of the kernel contract.
class Kernel {
 public:
  explicit Kernel(std::shared_ptr<DeviceContext> ctx) : ctx(std::move(ctx)) {}
  Kernel(const Kernel&) = delete;
  Kernel& operator=(const Kernel&) = delete;
  ~Kernel() {
    VkDevice device = ctx->device;
    if (pipeline) vkDestroyPipeline(device, pipeline, nullptr);
    if (pipelineLayout) vkDestroyPipelineLayout(device, pipelineLayout, nullptr);
    if (setLayout) vkDestroyDescriptorSetLayout(device, setLayout, nullptr);
    if (module) vkDestroyShaderModule(device, module, nullptr);
  }

  std::shared_ptr<DeviceContext> ctx;  // keeps the device alive as long as the kernel
  VkShaderModule module = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  uint32_t sampledTextures = 0;  // combined image samplers from kKernelFirstTextureBinding
  bool readsTable = false;       // a storage buffer at kKernelTableBinding
  // Set once the first (warm-up) dispatch has been submitted (RunResult::firstDispatchMs).
  std::atomic<bool> warmedUp{false};
  std::mutex warmUpMutex;
};

// Everything one run() creates. The destructor releases it on success and on throw.
struct RunResources {
  explicit RunResources(const DeviceContext& ctx) : ctx(ctx) {}
  RunResources(const RunResources&) = delete;
  RunResources& operator=(const RunResources&) = delete;
  ~RunResources() {
    commands.reset();  // first: it waits for a submit that we did not see finish
    if (queryPool) vkDestroyQueryPool(ctx.device, queryPool, nullptr);
    if (descriptorPool) vkDestroyDescriptorPool(ctx.device, descriptorPool, nullptr);  // and sets
  }                                                                                    // the buffers release themselves

  const DeviceContext& ctx;
  std::deque<MappedBuffer> inBuffers, outBuffers;  // one pair per plan segment
  std::optional<MappedBuffer> table;               // the kernel's table, when it reads one
  VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> sets;  // one per chunk
  VkQueryPool queryPool = VK_NULL_HANDLE;
  std::optional<OneShotCommands> commands;
};

// --- vulkan_device.cpp ------------------------------------------------------------------
bool isLavapipeName(const std::string& name);
void createInstance(DeviceContext& ctx, bool validation);
void createDevice(DeviceContext& ctx, const DeviceOptions& options);

// --- vulkan_buffers.cpp -----------------------------------------------------------------
void createBuffers(const DeviceContext& ctx, const ChunkPlan& plan, const std::vector<float>& inputs, uint32_t inStride,
                   RunResources& res);
// The table buffer (res.table), `table` copied in.
void createTableBuffer(const DeviceContext& ctx, const std::vector<float>& table, RunResources& res);
// Textures (gpu_texture.hpp) are written at kKernelFirstTextureBinding, ... of every
// chunk's set, and res.table, when there is one, whole at kKernelTableBinding.
void createDescriptorSets(const DeviceContext& ctx, const Kernel& kernel, const ChunkPlan& plan,
                          const std::vector<const GpuTexture*>& textures, RunResources& res);

}  // namespace mb::harness
