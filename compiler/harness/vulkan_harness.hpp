// A minimal Vulkan compute harness: runs a probe kernel over N records of floats and
// returns the outputs and the GPU time measured with timestamp queries.
//
// Kernel contract (emit/probe writes kernels that follow it):
//   layout(local_size_x = 64) in;
//   layout(std430, set = 0, binding = 0) readonly buffer MbIn  { float mbIn[];  };
//   layout(std430, set = 0, binding = 1) writeonly buffer MbOut { float mbOut[]; };
//   layout(push_constant) uniform MbPush { uint count; } mbPush;
// Record i of the current chunk reads mbIn[i*inStride ...] and writes mbOut[i*outStride ...];
// invocations with i >= count return at once. The harness splits a run into chunks so that
// no dispatch exceeds maxComputeWorkGroupCount[0] groups and no bound range exceeds
// maxStorageBufferRange, binding each chunk's sub-ranges (aligned to
// minStorageBufferOffsetAlignment). A kernel may also read a table of floats, the same for
// every record (a probe's LTC table):
//   layout(std430, set = 0, binding = 2) readonly buffer MbTable { float mbTable[]; };
#pragma once
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mb::harness {

// No usable Vulkan instance or device, or a Vulkan call failed. The message is one line.
class HarnessError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct DeviceOptions {
  // Case-insensitive substring of the device name to pick; empty = prefer lavapipe
  // ("llvmpipe"), else the first device with a compute queue.
  std::string device;
  // Enable VK_LAYER_KHRONOS_validation and capture every message it emits.
  bool validation = false;
  // Test hook: cap chunk sizes below the device limits (0 = use device limits).
  uint32_t maxRecordsPerChunk = 0;
  // Benchmark hook: false restores the behaviour before issue 15 (no warm-up dispatch, so a
  // kernel's first run() times lavapipe's JIT as GPU time); mb_bench_validate's old path.
  bool warmUpFirstDispatch = true;
};

struct RunResult {
  std::vector<float> outputs;  // count * outStride floats
  double gpuMs = 0.0;          // sum over chunks of timestamp deltas
  // Host time of the one-record dispatch that run() submits before the first run of a kernel,
  // 0 on later runs. Lavapipe JIT-compiles a pipeline at its first dispatch, inside the
  // timestamped interval: without this warm-up gpuMs would be mostly LLVM's compile time
  // (measured: 570-1300 ms for one 4096-record probe with Mesa's shader cache cold, against
  // 2-40 ms with it warm), and which runs paid it would depend on that cache.
  double firstDispatchMs = 0.0;
  uint32_t chunks = 0;
  // False when the queue has no timestamps (timestampValidBits == 0): gpuMs is then the
  // host-measured time from submit to fence signal.
  bool gpuTimestamps = true;
};

class Kernel;
class GpuTexture;  // harness/gpu_texture.hpp
struct DeviceContext;

class VulkanHarness {
 public:
  // Throws HarnessError("no Vulkan device ...") when there is none.
  explicit VulkanHarness(const DeviceOptions& options = {});
  ~VulkanHarness();
  VulkanHarness(const VulkanHarness&) = delete;
  VulkanHarness& operator=(const VulkanHarness&) = delete;

  std::string deviceName() const;
  // What a measurement on this device depends on: vendor and device id, driver version, name
  // and pipeline-cache UUID (which drivers change with every build), from
  // VkPhysicalDeviceProperties. Results cached under it are reused only on the same device
  // and driver (core/result_cache.hpp).
  std::string deviceIdentity() const;
  bool isLavapipe() const;
  uint32_t maxWorkGroupCountX() const;
  uint64_t maxStorageBufferRange() const;
  // VkPhysicalDeviceLimits::timestampPeriod: nanoseconds per timestamp tick (bench uses it
  // for the resolution of a timed dispatch).
  double timestampPeriodNs() const;
  // True when the device runs half arithmetic in shaders (shaderFloat16 of
  // VK_KHR_shader_float16_int8); the harness enables the feature whenever it is offered.
  bool supportsShaderFloat16() const;

  // Creates the compute pipeline for a kernel following the contract above. With
  // `sampledTextures` > 0 the kernel also declares that many combined image samplers at
  // set 0, bindings 2, 3, ... (e.g. `layout(set = 0, binding = 2) uniform samplerCube t;`),
  // given to run() in that order.
  // With `readsTable` it declares the table buffer instead (binding 2), given to run(); a
  // kernel does not have both.
  std::shared_ptr<Kernel> createKernel(const std::vector<uint32_t>& spirv, uint32_t sampledTextures = 0,
                                       bool readsTable = false);
  // The same, reusing the kernel made earlier for identical SPIR-V while it is among the last
  // kKernelCacheSize asked for: a pipeline that has run once keeps its JIT-compiled code, so
  // validating a permutation again in one process skips both the pipeline and the JIT.
  // Thread-safe.
  std::shared_ptr<Kernel> kernelFor(const std::vector<uint32_t>& spirv, bool readsTable = false);
  static constexpr size_t kKernelCacheSize = 64;

  // Runs `count` records. `inputs` holds count * inStride floats. Safe to call from
  // several threads at once (submissions to the one queue are serialized).
  RunResult run(Kernel& kernel, const std::vector<float>& inputs, uint32_t inStride, uint32_t outStride,
                uint64_t count);
  // The same for a kernel created with sampled textures: textures[k] is bound at binding 2 + k
  // (exactly as many as the kernel declares); for a kernel that reads a table, `table` (the
  // kernel's mbTable, copied to the device for this run).
  RunResult run(Kernel& kernel, const std::vector<float>& inputs, uint32_t inStride, uint32_t outStride, uint64_t count,
                const std::vector<const GpuTexture*>& textures, const std::vector<float>* table = nullptr);

  // The instance and device (vulkan_internal.hpp), for the harness's parts beside the compute
  // path: textures (gpu_texture.hpp) and graphics pipelines on the same device and queue.
  std::shared_ptr<DeviceContext> context() const;

  // Messages the validation layer emitted so far (empty when validation is off).
  std::vector<std::string> validationMessages() const;
  void clearValidationMessages();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mb::harness
