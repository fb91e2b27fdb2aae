// The harness's shared resource types (vulkan_resources.hpp).
#include "harness/vulkan_resources.hpp"

#include <chrono>
#include <mutex>

#include "harness/vulkan_check.hpp"
#include "harness/vulkan_internal.hpp"

namespace mb::harness {
namespace {

// A preview takes well under a second on lavapipe and a big stress run seconds; five minutes
// means the work hung, and a clear error beats a test that never ends.
constexpr uint64_t kFenceTimeoutSeconds = 300;

}  // namespace

uint32_t findMemoryType(const DeviceContext& ctx, uint32_t allowedTypes,
                        std::initializer_list<VkMemoryPropertyFlags> preferred, const std::string& what) {
  for (VkMemoryPropertyFlags wanted : preferred) {
    for (uint32_t i = 0; i < ctx.memory.memoryTypeCount; ++i) {
      if ((allowedTypes & (1u << i)) && (ctx.memory.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
    }
  }
  throw HarnessError("the device has no " + what);
}

// --- MappedBuffer -----------------------------------------------------------------------

MappedBuffer::~MappedBuffer() {
  if (buffer) vkDestroyBuffer(device_, buffer, nullptr);
  if (memory) vkFreeMemory(device_, memory, nullptr);  // unmaps implicitly
}

void MappedBuffer::create(const DeviceContext& ctx, uint64_t bytes, VkBufferUsageFlags usage) {
  device_ = ctx.device;
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = bytes;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  MB_VK_CHECK(vkCreateBuffer(device_, &info, nullptr, &buffer));

  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(device_, buffer, &req);
  const VkMemoryPropertyFlags required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  VkMemoryAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex =
      findMemoryType(ctx, req.memoryTypeBits, {required | VK_MEMORY_PROPERTY_HOST_CACHED_BIT, required},
                     "host-visible, host-coherent memory for buffers");
  MB_VK_CHECK(vkAllocateMemory(device_, &alloc, nullptr, &memory));
  MB_VK_CHECK(vkBindBufferMemory(device_, buffer, memory, 0));
  MB_VK_CHECK(vkMapMemory(device_, memory, 0, VK_WHOLE_SIZE, 0, &mapped));
}

// --- DeviceImage ------------------------------------------------------------------------

DeviceImage::~DeviceImage() {
  if (view) vkDestroyImageView(device_, view, nullptr);
  if (image) vkDestroyImage(device_, image, nullptr);
  if (memory) vkFreeMemory(device_, memory, nullptr);
}

void DeviceImage::create(const DeviceContext& ctx, const VkImageCreateInfo& info, VkImageViewType viewType,
                         VkImageAspectFlags aspect) {
  device_ = ctx.device;
  MB_VK_CHECK(vkCreateImage(device_, &info, nullptr, &image));
  VkMemoryRequirements req{};
  vkGetImageMemoryRequirements(device_, image, &req);
  VkMemoryAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = findMemoryType(
      ctx, req.memoryTypeBits, {VkMemoryPropertyFlags{VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT}, VkMemoryPropertyFlags{0}},
      "memory type for an image");
  MB_VK_CHECK(vkAllocateMemory(device_, &alloc, nullptr, &memory));
  MB_VK_CHECK(vkBindImageMemory(device_, image, memory, 0));

  VkImageViewCreateInfo viewInfo{};
  viewInfo.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
  viewInfo.image = image;
  viewInfo.viewType = viewType;
  viewInfo.format = info.format;
  viewInfo.subresourceRange = {aspect, 0, info.mipLevels, 0, info.arrayLayers};
  MB_VK_CHECK(vkCreateImageView(device_, &viewInfo, nullptr, &view));
}

// --- OneShotCommands --------------------------------------------------------------------

OneShotCommands::OneShotCommands(const DeviceContext& ctx) : ctx_(ctx) {
  // A constructor that throws runs no destructor: release what was made here.
  try {
    VkCommandPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    poolInfo.queueFamilyIndex = ctx.queueFamily;
    MB_VK_CHECK(vkCreateCommandPool(ctx.device, &poolInfo, nullptr, &pool_));

    VkCommandBufferAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    alloc.commandPool = pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    MB_VK_CHECK(vkAllocateCommandBuffers(ctx.device, &alloc, &cmd_));

    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    MB_VK_CHECK(vkBeginCommandBuffer(cmd_, &begin));
  } catch (...) {
    if (pool_) vkDestroyCommandPool(ctx.device, pool_, nullptr);
    throw;
  }
}

OneShotCommands::~OneShotCommands() {
  // A submit that we did not see finish may still use the command buffer and its resources.
  if (inFlight_) {
    std::lock_guard lock(ctx_.queueMutex);
    vkDeviceWaitIdle(ctx_.device);
  }
  if (fence_) vkDestroyFence(ctx_.device, fence_, nullptr);
  if (pool_) vkDestroyCommandPool(ctx_.device, pool_, nullptr);  // frees cmd_
}

double OneShotCommands::submitAndWait(const std::string& what) {
  MB_VK_CHECK(vkEndCommandBuffer(cmd_));
  VkFenceCreateInfo fenceInfo{};
  fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  MB_VK_CHECK(vkCreateFence(ctx_.device, &fenceInfo, nullptr, &fence_));

  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd_;
  const auto start = std::chrono::steady_clock::now();
  {
    std::lock_guard lock(ctx_.queueMutex);
    MB_VK_CHECK(vkQueueSubmit(ctx_.queue, 1, &submit, fence_));
  }
  inFlight_ = true;
  const VkResult waited = vkWaitForFences(ctx_.device, 1, &fence_, VK_TRUE, kFenceTimeoutSeconds * 1000 * 1000 * 1000);
  if (waited == VK_TIMEOUT) {
    throw HarnessError(what + " did not finish within " + std::to_string(kFenceTimeoutSeconds) + " s");
  }
  MB_VK_CHECK(waited);
  inFlight_ = false;
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace mb::harness
