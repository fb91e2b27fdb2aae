// The Vulkan resources every path of the harness makes (compute runs, textures, graphics):
// the choice of a memory type, a mapped host-visible buffer, an image in device memory with
// its view, and a command buffer recorded once, submitted once and waited for. Each type
// owns what it creates and releases it on every exit path, including a throw half-way
// through its creation. Private to compiler/harness (gpu_texture.hpp holds a DeviceImage).
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <initializer_list>
#include <string>

namespace mb::harness {

struct DeviceContext;  // vulkan_internal.hpp

// The first memory type allowed by `allowedTypes` (VkMemoryRequirements::memoryTypeBits)
// that has every flag of the first `preferred` set that any allowed type has; throws
// HarnessError("the device has no " + what) when none has any of them.
uint32_t findMemoryType(const DeviceContext& ctx, uint32_t allowedTypes,
                        std::initializer_list<VkMemoryPropertyFlags> preferred, const std::string& what);

// A buffer in host-visible, coherent memory (cached where the device has it: the host reads
// outputs and read-backs), mapped for its whole life; coherent, so no flushes or invalidates.
class MappedBuffer {
 public:
  // Neither copied nor moved: keep several in a std::deque, whose elements stay in place.
  MappedBuffer() = default;
  MappedBuffer(const MappedBuffer&) = delete;
  MappedBuffer& operator=(const MappedBuffer&) = delete;
  ~MappedBuffer();

  // Creates, allocates, binds and maps `bytes` bytes; on a throw the destructor releases
  // whatever was made. Only on an empty buffer.
  void create(const DeviceContext& ctx, uint64_t bytes, VkBufferUsageFlags usage);

  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;

 private:
  VkDevice device_ = VK_NULL_HANDLE;
};

// An image in device-local memory where the device has it (a discrete GPU; lavapipe's one
// heap is both), with one view over all its mip levels and layers.
class DeviceImage {
 public:
  DeviceImage() = default;
  DeviceImage(const DeviceImage&) = delete;
  DeviceImage& operator=(const DeviceImage&) = delete;
  ~DeviceImage();

  // Creates the image from `info`, allocates and binds its memory and makes the view; on a
  // throw the destructor releases whatever was made. Only on an empty image.
  void create(const DeviceContext& ctx, const VkImageCreateInfo& info, VkImageViewType viewType,
              VkImageAspectFlags aspect);

  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;

 private:
  VkDevice device_ = VK_NULL_HANDLE;
};

// One primary command buffer from a transient pool on the harness's queue family, begun for
// one submit at construction. The destructor waits for the device when a submit is still in
// flight (a throw while waiting), so whatever the commands use must be released after it.
class OneShotCommands {
 public:
  explicit OneShotCommands(const DeviceContext& ctx);
  OneShotCommands(const OneShotCommands&) = delete;
  OneShotCommands& operator=(const OneShotCommands&) = delete;
  ~OneShotCommands();

  VkCommandBuffer cmd() const { return cmd_; }
  // Ends recording, submits once under the queue lock and waits for the fence; returns the
  // host-measured submit-to-signal time in ms. A hang throws "<what> did not finish within
  // 300 s".
  double submitAndWait(const std::string& what);

 private:
  const DeviceContext& ctx_;
  VkCommandPool pool_ = VK_NULL_HANDLE;  // frees cmd_ with it
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  bool inFlight_ = false;
};

}  // namespace mb::harness
