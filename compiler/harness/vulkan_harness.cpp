// The Vulkan compute harness (see vulkan_harness.hpp for the kernel contract).
//
// Ownership: a DeviceContext owns the instance, the debug messenger and the device. The
// harness and every Kernel hold it through a shared_ptr, so a kernel that outlives its
// harness still destroys its pipeline before the device goes away. Everything a single
// run() creates lives in a RunResources object that releases it on every exit path.
#include "harness/vulkan_harness.hpp"

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstring>
#include <mutex>

#include "harness/chunk_plan.hpp"
#include "harness/vulkan_check.hpp"

namespace mb::harness {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr const char* kNoDeviceHint =
    "install mesa-vulkan-drivers or set VK_ICD_FILENAMES to a driver's ICD json";
// Keeps each buffer allocation modest even where maxMemoryAllocationSize is huge: host-
// visible heaps are often small on discrete GPUs, and a run rarely needs more.
constexpr uint64_t kMaxSegmentBytes = uint64_t{256} << 20;
// A probe run takes well under a second on lavapipe and a big stress run seconds; five
// minutes means the kernel hung, and a clear error beats a test that never ends.
constexpr uint64_t kFenceTimeoutSeconds = 300;

std::string toLower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool containsNoCase(const std::string& haystack, const std::string& needle) {
  return toLower(haystack).find(toLower(needle)) != std::string::npos;
}

bool isLavapipeName(const std::string& name) { return containsNoCase(name, "llvmpipe"); }

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

VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data,
                                              void* userData) {
  std::string text =
      (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error: " : "warning: ";
  if (data && data->pMessageIdName) text += std::string("[") + data->pMessageIdName + "] ";
  if (data && data->pMessage) text += data->pMessage;
  static_cast<MessageLog*>(userData)->add(std::move(text));
  return VK_FALSE;  // never abort the call: the caller decides what a message means
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(MessageLog* log) {
  VkDebugUtilsMessengerCreateInfoEXT info{};
  info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = onDebugMessage;
  info.pUserData = log;
  return info;
}

bool hasInstanceLayer(const char* name) {
  uint32_t count = 0;
  if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkLayerProperties> layers(count);
  if (vkEnumerateInstanceLayerProperties(&count, layers.data()) < 0) return false;
  return std::any_of(layers.begin(), layers.begin() + count,
                     [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

// `layer` null: extensions of the loader and the drivers.
bool hasInstanceExtension(const char* name, const char* layer) {
  uint32_t count = 0;
  if (vkEnumerateInstanceExtensionProperties(layer, &count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> exts(count);
  if (vkEnumerateInstanceExtensionProperties(layer, &count, exts.data()) < 0) return false;
  return std::any_of(exts.begin(), exts.begin() + count, [&](const VkExtensionProperties& e) {
    return std::strcmp(e.extensionName, name) == 0;
  });
}

bool hasDeviceExtension(VkPhysicalDevice device, const char* name) {
  uint32_t count = 0;
  if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr) != VK_SUCCESS)
    return false;
  std::vector<VkExtensionProperties> exts(count);
  if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, exts.data()) < 0) return false;
  return std::any_of(exts.begin(), exts.begin() + count, [&](const VkExtensionProperties& e) {
    return std::strcmp(e.extensionName, name) == 0;
  });
}

// A physical device that can run compute, with the queue family we would use on it.
struct Candidate {
  VkPhysicalDevice device = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties props{};
  uint32_t queueFamily = 0;
  uint32_t timestampValidBits = 0;
};

// The first compute family, preferring one that has timestamps. False if none computes.
bool findComputeFamily(Candidate& c) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(c.device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(c.device, &count, families.data());
  bool found = false;
  for (uint32_t i = 0; i < count; ++i) {
    if (!(families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) || families[i].queueCount == 0) continue;
    if (!found || (c.timestampValidBits == 0 && families[i].timestampValidBits > 0)) {
      c.queueFamily = i;
      c.timestampValidBits = families[i].timestampValidBits;
      found = true;
    }
  }
  return found;
}

std::string joinNames(const std::vector<Candidate>& candidates) {
  std::string names;
  for (const Candidate& c : candidates) {
    if (!names.empty()) names += ", ";
    names += std::string("\"") + c.props.deviceName + "\"";
  }
  return names;
}

const Candidate& chooseCandidate(const std::vector<Candidate>& candidates,
                                 const std::string& wanted) {
  if (wanted.empty()) {
    for (const Candidate& c : candidates)
      if (isLavapipeName(c.props.deviceName)) return c;
    return candidates.front();
  }
  for (const Candidate& c : candidates)
    if (containsNoCase(c.props.deviceName, wanted)) return c;
  throw HarnessError("no Vulkan device matches \"" + wanted +
                     "\"; available: " + joinNames(candidates));
}

}  // namespace

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

namespace {

void createInstance(DeviceContext& ctx, bool validation) {
  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  if (validation) {
    if (!hasInstanceLayer(kValidationLayer)) {
      throw HarnessError(std::string("validation was requested but ") + kValidationLayer +
                         " is not installed (install vulkan-validationlayers)");
    }
    if (!hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME, nullptr) &&
        !hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME, kValidationLayer)) {
      throw HarnessError("validation was requested but VK_EXT_debug_utils is not available");
    }
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  VkInstanceCreateFlags flags = 0;
  // MoltenVK and other non-conformant drivers are only listed when asked for.
  if (hasInstanceExtension(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME, nullptr)) {
    extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
    flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
  }

  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "matbricks";
  app.pEngineName = "matbricks-harness";
  app.apiVersion = VK_API_VERSION_1_1;

  // Chained so that messages from vkCreateInstance / vkDestroyInstance are caught too.
  const VkDebugUtilsMessengerCreateInfoEXT debugInfo = messengerInfo(&ctx.log);
  VkInstanceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  info.pNext = validation ? &debugInfo : nullptr;
  info.flags = flags;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();

  const VkResult result = vkCreateInstance(&info, nullptr, &ctx.instance);
  if (result != VK_SUCCESS) {
    ctx.instance = VK_NULL_HANDLE;
    throw HarnessError("no Vulkan device found (vkCreateInstance: " + vkResultName(result) +
                       "); " + kNoDeviceHint);
  }
  if (!validation) return;

  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(ctx.instance, "vkCreateDebugUtilsMessengerEXT"));
  ctx.destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(ctx.instance, "vkDestroyDebugUtilsMessengerEXT"));
  if (!create || !ctx.destroyMessenger) {
    throw HarnessError("validation was requested but vkCreateDebugUtilsMessengerEXT is missing");
  }
  MB_VK_CHECK(create(ctx.instance, &debugInfo, nullptr, &ctx.messenger));
}

std::vector<Candidate> computeCandidates(VkInstance instance) {
  uint32_t count = 0;
  const VkResult result = vkEnumeratePhysicalDevices(instance, &count, nullptr);
  if (result < 0 || count == 0) {
    const std::string why = result < 0 ? vkResultName(result) : std::string("0 devices");
    throw HarnessError("no Vulkan device found (vkEnumeratePhysicalDevices: " + why + "); " +
                       kNoDeviceHint);
  }
  std::vector<VkPhysicalDevice> devices(count);
  MB_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
  devices.resize(count);

  std::vector<Candidate> candidates;
  for (VkPhysicalDevice device : devices) {
    Candidate c;
    c.device = device;
    vkGetPhysicalDeviceProperties(device, &c.props);
    if (findComputeFamily(c)) candidates.push_back(c);
  }
  if (candidates.empty()) {
    throw HarnessError("no Vulkan device found (none of " + std::to_string(count) +
                       " devices has a compute queue); " + kNoDeviceHint);
  }
  return candidates;
}

// maxMemoryAllocationSize is a Vulkan 1.1 property; 1.0 devices keep our own cap.
uint64_t maxAllocationBytes(VkPhysicalDevice device, uint32_t apiVersion) {
  if (apiVersion < VK_API_VERSION_1_1) return kMaxSegmentBytes;
  VkPhysicalDeviceMaintenance3Properties m3{};
  m3.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES;
  VkPhysicalDeviceProperties2 props{};
  props.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
  props.pNext = &m3;
  vkGetPhysicalDeviceProperties2(device, &props);
  return std::min<uint64_t>(kMaxSegmentBytes, m3.maxMemoryAllocationSize);
}

// shaderFloat16 through VK_KHR_shader_float16_int8: the instance asks for Vulkan 1.1, where
// the feature is an extension (core, and in VkPhysicalDeviceVulkan12Features, from 1.2 on).
bool offersShaderFloat16(VkPhysicalDevice device) {
  if (!hasDeviceExtension(device, VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME)) return false;
  VkPhysicalDeviceShaderFloat16Int8FeaturesKHR f16{};
  f16.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES_KHR;
  VkPhysicalDeviceFeatures2 features{};
  features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
  features.pNext = &f16;
  vkGetPhysicalDeviceFeatures2(device, &features);
  return f16.shaderFloat16 == VK_TRUE;
}

void createDevice(DeviceContext& ctx, const DeviceOptions& options) {
  const std::vector<Candidate> candidates = computeCandidates(ctx.instance);
  const Candidate& chosen = chooseCandidate(candidates, options.device);
  ctx.physical = chosen.device;
  ctx.props = chosen.props;
  ctx.queueFamily = chosen.queueFamily;
  ctx.timestampValidBits = chosen.timestampValidBits;
  vkGetPhysicalDeviceMemoryProperties(ctx.physical, &ctx.memory);
  ctx.maxSegmentBytes = maxAllocationBytes(ctx.physical, ctx.props.apiVersion);

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{};
  queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  queueInfo.queueFamilyIndex = ctx.queueFamily;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  // The spec requires enabling it wherever a (portability) driver offers it.
  std::vector<const char*> extensions;
  if (hasDeviceExtension(ctx.physical, "VK_KHR_portability_subset"))
    extensions.push_back("VK_KHR_portability_subset");
  // Half arithmetic only; the probe buffers stay fp32, so no 16-bit storage feature is needed.
  VkPhysicalDeviceShaderFloat16Int8FeaturesKHR f16{};
  f16.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES_KHR;
  ctx.shaderFloat16 = offersShaderFloat16(ctx.physical);
  if (ctx.shaderFloat16) {
    extensions.push_back(VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME);
    f16.shaderFloat16 = VK_TRUE;
  }

  VkDeviceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  info.pNext = ctx.shaderFloat16 ? &f16 : nullptr;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  MB_VK_CHECK(vkCreateDevice(ctx.physical, &info, nullptr, &ctx.device));
  vkGetDeviceQueue(ctx.device, ctx.queueFamily, 0, &ctx.queue);
}

}  // namespace

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
};

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
  VkDescriptorSetLayoutBinding bindings[2]{};
  for (uint32_t i = 0; i < 2; ++i) {
    bindings[i].binding = i;  // 0 = MbIn, 1 = MbOut
    bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    bindings[i].descriptorCount = 1;
    bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  }
  VkDescriptorSetLayoutCreateInfo setInfo{};
  setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  setInfo.bindingCount = 2;
  setInfo.pBindings = bindings;
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
  MB_VK_CHECK(
      vkCreateComputePipelines(k.ctx->device, VK_NULL_HANDLE, 1, &info, nullptr, &k.pipeline));
}

struct MappedBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
};

// Everything one run() creates. The destructor releases it on success and on throw.
struct RunResources {
  explicit RunResources(const DeviceContext& ctx) : ctx(ctx), device(ctx.device) {}
  RunResources(const RunResources&) = delete;
  RunResources& operator=(const RunResources&) = delete;
  ~RunResources() {
    // A submit that we did not see finish may still use these objects.
    if (inFlight) {
      std::lock_guard lock(ctx.queueMutex);
      vkDeviceWaitIdle(device);
    }
    if (fence) vkDestroyFence(device, fence, nullptr);
    if (commandPool) vkDestroyCommandPool(device, commandPool, nullptr);  // frees the cb
    if (queryPool) vkDestroyQueryPool(device, queryPool, nullptr);
    if (descriptorPool) vkDestroyDescriptorPool(device, descriptorPool, nullptr);  // and sets
    for (auto* list : {&inBuffers, &outBuffers}) {
      for (MappedBuffer& b : *list) {
        if (b.buffer) vkDestroyBuffer(device, b.buffer, nullptr);
        if (b.memory) vkFreeMemory(device, b.memory, nullptr);  // unmaps implicitly
      }
    }
  }

  const DeviceContext& ctx;
  VkDevice device;
  std::vector<MappedBuffer> inBuffers, outBuffers;  // one pair per plan segment
  VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> sets;  // one per chunk
  VkQueryPool queryPool = VK_NULL_HANDLE;
  VkCommandPool commandPool = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  bool inFlight = false;
};

// Host-visible and coherent, so no flushes or invalidates are needed; cached if possible
// because the host reads every output back.
uint32_t hostMemoryType(const DeviceContext& ctx, uint32_t allowedTypes) {
  const VkMemoryPropertyFlags required =
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  for (VkMemoryPropertyFlags wanted : {required | VK_MEMORY_PROPERTY_HOST_CACHED_BIT, required}) {
    for (uint32_t i = 0; i < ctx.memory.memoryTypeCount; ++i) {
      if ((allowedTypes & (1u << i)) &&
          (ctx.memory.memoryTypes[i].propertyFlags & wanted) == wanted)
        return i;
    }
  }
  throw HarnessError("the device has no host-visible, host-coherent memory for storage buffers");
}

void createMappedBuffer(const DeviceContext& ctx, uint64_t bytes, MappedBuffer& b) {
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = bytes;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
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
void createBuffers(const DeviceContext& ctx, const ChunkPlan& plan,
                   const std::vector<float>& inputs, uint32_t inStride, RunResources& res) {
  for (const Segment& seg : plan.segments) {
    MappedBuffer& in = res.inBuffers.emplace_back();
    createMappedBuffer(ctx, seg.inBytes, in);
    std::memset(in.mapped, 0, seg.inBytes);  // stride-0 dummy bytes stay defined
    const size_t floats = seg.records * inStride;
    if (floats) {
      std::memcpy(in.mapped, inputs.data() + seg.firstRecord * inStride, floats * sizeof(float));
    }
    createMappedBuffer(ctx, seg.outBytes, res.outBuffers.emplace_back());
  }
}

// One descriptor set per chunk: all chunks are recorded into one command buffer, and a set
// must not change while a recorded command still refers to it.
void createDescriptorSets(const DeviceContext& ctx, const Kernel& kernel, const ChunkPlan& plan,
                          RunResources& res) {
  const auto setCount = static_cast<uint32_t>(plan.chunks.size());
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2 * setCount};
  VkDescriptorPoolCreateInfo poolInfo{};
  poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  poolInfo.maxSets = setCount;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &size;
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
  }
  vkUpdateDescriptorSets(ctx.device, static_cast<uint32_t>(writes.size()), writes.data(), 0,
                         nullptr);
}

void createQueryPool(const DeviceContext& ctx, uint32_t chunkCount, RunResources& res) {
  if (ctx.timestampValidBits == 0) return;  // run() falls back to wall time
  VkQueryPoolCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = 2 * chunkCount;
  MB_VK_CHECK(vkCreateQueryPool(ctx.device, &info, nullptr, &res.queryPool));
}

void allocateCommandBuffer(const DeviceContext& ctx, RunResources& res) {
  VkCommandPoolCreateInfo poolInfo{};
  poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  poolInfo.queueFamilyIndex = ctx.queueFamily;
  MB_VK_CHECK(vkCreateCommandPool(ctx.device, &poolInfo, nullptr, &res.commandPool));

  VkCommandBufferAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  alloc.commandPool = res.commandPool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  MB_VK_CHECK(vkAllocateCommandBuffers(ctx.device, &alloc, &res.cmd));
}

// All chunks in one command buffer. Chunks touch disjoint ranges, so no barriers between
// dispatches; one barrier at the end makes the shader writes visible to the host.
void recordCommands(const Kernel& kernel, const ChunkPlan& plan, RunResources& res) {
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  MB_VK_CHECK(vkBeginCommandBuffer(res.cmd, &begin));

  const auto chunkCount = static_cast<uint32_t>(plan.chunks.size());
  if (res.queryPool) vkCmdResetQueryPool(res.cmd, res.queryPool, 0, 2 * chunkCount);
  vkCmdBindPipeline(res.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernel.pipeline);
  for (uint32_t i = 0; i < chunkCount; ++i) {
    const uint32_t count = plan.chunks[i].records;
    vkCmdBindDescriptorSets(res.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernel.pipelineLayout, 0, 1,
                            &res.sets[i], 0, nullptr);
    vkCmdPushConstants(res.cmd, kernel.pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0,
                       sizeof(count), &count);
    // Both stamps at the compute stage: the first waits for the previous chunk's shaders,
    // so chunk intervals do not overlap and their sum does not count time twice.
    if (res.queryPool)
      vkCmdWriteTimestamp(res.cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, res.queryPool, 2 * i);
    vkCmdDispatch(res.cmd, (count + kLocalSizeX - 1) / kLocalSizeX, 1, 1);
    if (res.queryPool)
      vkCmdWriteTimestamp(res.cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, res.queryPool, 2 * i + 1);
  }
  VkMemoryBarrier toHost{};
  toHost.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(res.cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                       0, 1, &toHost, 0, nullptr, 0, nullptr);
  MB_VK_CHECK(vkEndCommandBuffer(res.cmd));
}

// Submits once and waits; returns the host-measured submit-to-signal time in ms.
double submitAndWait(const DeviceContext& ctx, RunResources& res) {
  VkFenceCreateInfo fenceInfo{};
  fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  MB_VK_CHECK(vkCreateFence(ctx.device, &fenceInfo, nullptr, &res.fence));

  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &res.cmd;
  const auto start = std::chrono::steady_clock::now();
  {
    std::lock_guard lock(ctx.queueMutex);
    MB_VK_CHECK(vkQueueSubmit(ctx.queue, 1, &submit, res.fence));
  }
  res.inFlight = true;
  const VkResult waited = vkWaitForFences(ctx.device, 1, &res.fence, VK_TRUE,
                                         kFenceTimeoutSeconds * 1000 * 1000 * 1000);
  if (waited == VK_TIMEOUT) {
    throw HarnessError("the kernel did not finish within " +
                       std::to_string(kFenceTimeoutSeconds) + " s");
  }
  MB_VK_CHECK(waited);
  res.inFlight = false;
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// Sum over chunks of (end - begin) ticks, converted with timestampPeriod (ns per tick).
double timestampMs(const DeviceContext& ctx, uint32_t chunkCount, const RunResources& res) {
  std::vector<uint64_t> stamps(2 * size_t{chunkCount});
  MB_VK_CHECK(vkGetQueryPoolResults(ctx.device, res.queryPool, 0, 2 * chunkCount,
                                    stamps.size() * sizeof(uint64_t), stamps.data(),
                                    sizeof(uint64_t),
                                    VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  // Only the low timestampValidBits bits count; masking the difference handles wrap-around.
  const uint64_t mask = ctx.timestampValidBits >= 64
                            ? ~uint64_t{0}
                            : (uint64_t{1} << ctx.timestampValidBits) - 1;
  double ns = 0;
  for (uint32_t i = 0; i < chunkCount; ++i) {
    const uint64_t ticks = (stamps[2 * i + 1] - stamps[2 * i]) & mask;
    ns += static_cast<double>(ticks) * ctx.props.limits.timestampPeriod;
  }
  return ns / 1e6;
}

void copyOutputs(const ChunkPlan& plan, uint32_t outStride, const RunResources& res,
                 std::vector<float>& outputs) {
  for (size_t s = 0; s < plan.segments.size(); ++s) {
    const Segment& seg = plan.segments[s];
    const size_t floats = seg.records * outStride;
    if (floats == 0) continue;
    std::memcpy(outputs.data() + seg.firstRecord * outStride, res.outBuffers[s].mapped,
                floats * sizeof(float));
  }
}

}  // namespace

struct VulkanHarness::Impl {
  std::shared_ptr<DeviceContext> ctx;
  DeviceOptions options;
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

bool VulkanHarness::isLavapipe() const { return isLavapipeName(deviceName()); }

uint32_t VulkanHarness::maxWorkGroupCountX() const {
  return impl_->ctx->props.limits.maxComputeWorkGroupCount[0];
}

uint64_t VulkanHarness::maxStorageBufferRange() const {
  return impl_->ctx->props.limits.maxStorageBufferRange;
}

bool VulkanHarness::supportsShaderFloat16() const { return impl_->ctx->shaderFloat16; }

std::shared_ptr<Kernel> VulkanHarness::createKernel(const std::vector<uint32_t>& spirv) {
  auto kernel = std::make_shared<Kernel>(impl_->ctx);
  createShaderModule(*kernel, spirv);
  createLayouts(*kernel);
  createPipeline(*kernel);
  return kernel;
}

RunResult VulkanHarness::run(Kernel& kernel, const std::vector<float>& inputs, uint32_t inStride,
                             uint32_t outStride, uint64_t count) {
  const DeviceContext& ctx = *impl_->ctx;
  if (kernel.ctx.get() != &ctx) throw HarnessError("run: the kernel belongs to another harness");
  if (inputs.size() != count * inStride) {
    throw HarnessError("run: expected " + std::to_string(count) + " records x " +
                       std::to_string(inStride) + " floats = " + std::to_string(count * inStride) +
                       " inputs, got " + std::to_string(inputs.size()));
  }
  RunResult result;
  if (count == 0) return result;

  ChunkLimits limits;
  limits.maxGroupsX = ctx.props.limits.maxComputeWorkGroupCount[0];
  limits.maxRangeBytes = ctx.props.limits.maxStorageBufferRange;
  limits.offsetAlignment = ctx.props.limits.minStorageBufferOffsetAlignment;
  limits.maxSegmentBytes = ctx.maxSegmentBytes;
  limits.recordCap = impl_->options.maxRecordsPerChunk;
  const ChunkPlan plan = planChunks(count, inStride, outStride, limits);
  const auto chunkCount = static_cast<uint32_t>(plan.chunks.size());

  RunResources res(ctx);
  createBuffers(ctx, plan, inputs, inStride, res);
  createDescriptorSets(ctx, kernel, plan, res);
  createQueryPool(ctx, chunkCount, res);
  allocateCommandBuffer(ctx, res);
  recordCommands(kernel, plan, res);
  const double wallMs = submitAndWait(ctx, res);

  result.chunks = chunkCount;
  result.gpuTimestamps = res.queryPool != VK_NULL_HANDLE;
  result.gpuMs = result.gpuTimestamps ? timestampMs(ctx, chunkCount, res) : wallMs;
  result.outputs.resize(count * outStride);
  copyOutputs(plan, outStride, res, result.outputs);
  return result;
}

std::vector<std::string> VulkanHarness::validationMessages() const {
  return impl_->ctx->log.snapshot();
}

void VulkanHarness::clearValidationMessages() { impl_->ctx->log.clear(); }

}  // namespace mb::harness
