// Instance and device for the harness: the validation message log's callback, instance
// creation (with the validation layer and the debug messenger when asked for), the choice
// of a physical device with a compute queue (lavapipe unless a name is given), and device
// creation with the features the probes need (shaderFloat16 where offered).
#include <algorithm>
#include <cctype>
#include <cstring>

#include "harness/sampler_precision.hpp"
#include "harness/vulkan_check.hpp"
#include "harness/vulkan_internal.hpp"

namespace mb::harness {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr const char* kNoDeviceHint = "install mesa-vulkan-drivers or set VK_ICD_FILENAMES to a driver's ICD json";

std::string toLower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool containsNoCase(const std::string& haystack, const std::string& needle) {
  return toLower(haystack).find(toLower(needle)) != std::string::npos;
}

VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data, void* userData) {
  std::string text = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error: " : "warning: ";
  if (data && data->pMessageIdName) text += std::string("[") + data->pMessageIdName + "] ";
  if (data && data->pMessage) text += data->pMessage;
  static_cast<MessageLog*>(userData)->add(std::move(text));
  return VK_FALSE;  // never abort the call: the caller decides what a message means
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(MessageLog* log) {
  VkDebugUtilsMessengerCreateInfoEXT info{};
  info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
  info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
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
  return std::any_of(exts.begin(), exts.begin() + count,
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

bool hasDeviceExtension(VkPhysicalDevice device, const char* name) {
  uint32_t count = 0;
  if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> exts(count);
  if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, exts.data()) < 0) return false;
  return std::any_of(exts.begin(), exts.begin() + count,
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

// A physical device that can run compute, with the queue family we would use on it.
struct Candidate {
  VkPhysicalDevice device = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties props{};
  uint32_t queueFamily = 0;
  uint32_t timestampValidBits = 0;
  bool graphics = false;
};

// The first compute family, preferring one that has timestamps and then one that also has
// graphics (the preview's render passes, vulkan_graphics.cpp; lavapipe's single family has
// all three). False if none computes.
bool findComputeFamily(Candidate& c) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(c.device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(c.device, &count, families.data());
  auto score = [](const VkQueueFamilyProperties& f) {
    return (f.timestampValidBits > 0 ? 2 : 0) + ((f.queueFlags & VK_QUEUE_GRAPHICS_BIT) ? 1 : 0);
  };
  bool found = false;
  int best = -1;
  for (uint32_t i = 0; i < count; ++i) {
    if (!(families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) || families[i].queueCount == 0) continue;
    if (score(families[i]) > best) {
      best = score(families[i]);
      c.queueFamily = i;
      c.timestampValidBits = families[i].timestampValidBits;
      c.graphics = (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) != 0;
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

const Candidate& chooseCandidate(const std::vector<Candidate>& candidates, const std::string& wanted) {
  if (wanted.empty()) {
    for (const Candidate& c : candidates)
      if (isLavapipeName(c.props.deviceName)) return c;
    return candidates.front();
  }
  for (const Candidate& c : candidates)
    if (containsNoCase(c.props.deviceName, wanted)) return c;
  throw HarnessError("no Vulkan device matches \"" + wanted + "\"; available: " + joinNames(candidates));
}

std::vector<Candidate> computeCandidates(VkInstance instance) {
  uint32_t count = 0;
  const VkResult result = vkEnumeratePhysicalDevices(instance, &count, nullptr);
  if (result < 0 || count == 0) {
    const std::string why = result < 0 ? vkResultName(result) : std::string("0 devices");
    throw HarnessError("no Vulkan device found (vkEnumeratePhysicalDevices: " + why + "); " + kNoDeviceHint);
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
    throw HarnessError("no Vulkan device found (none of " + std::to_string(count) + " devices has a compute queue); " +
                       kNoDeviceHint);
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

}  // namespace

bool isLavapipeName(const std::string& name) { return containsNoCase(name, "llvmpipe"); }

SamplerPrecision samplerPrecision(const VulkanHarness& gpu) {
  const VkPhysicalDeviceLimits& limits = gpu.context()->props.limits;
  return {limits.subTexelPrecisionBits, limits.mipmapPrecisionBits};
}

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
    throw HarnessError("no Vulkan device found (vkCreateInstance: " + vkResultName(result) + "); " + kNoDeviceHint);
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

void createDevice(DeviceContext& ctx, const DeviceOptions& options) {
  const std::vector<Candidate> candidates = computeCandidates(ctx.instance);
  const Candidate& chosen = chooseCandidate(candidates, options.device);
  ctx.physical = chosen.device;
  ctx.props = chosen.props;
  ctx.queueFamily = chosen.queueFamily;
  ctx.timestampValidBits = chosen.timestampValidBits;
  ctx.graphics = chosen.graphics;
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
  if (hasDeviceExtension(ctx.physical, "VK_KHR_portability_subset")) extensions.push_back("VK_KHR_portability_subset");
  // Half arithmetic only; the probe buffers stay fp32, so no 16-bit storage feature is needed.
  VkPhysicalDeviceShaderFloat16Int8FeaturesKHR f16{};
  f16.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES_KHR;
  ctx.shaderFloat16 = offersShaderFloat16(ctx.physical);
  if (ctx.shaderFloat16) {
    extensions.push_back(VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME);
    f16.shaderFloat16 = VK_TRUE;
  }

  // VK_KHR_maintenance4's relaxed interface matching: a fragment shader may leave some of the
  // vertex shader's outputs unread (a permutation that shades without the tangent or uv0 of
  // the fragment stage's fixed interface, docs/fragment-stage.md), which the validation layer
  // otherwise reports as a performance warning for every such pipeline.
  VkPhysicalDeviceMaintenance4FeaturesKHR maintenance4{};
  maintenance4.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_FEATURES_KHR;
  if (hasDeviceExtension(ctx.physical, VK_KHR_MAINTENANCE_4_EXTENSION_NAME)) {
    extensions.push_back(VK_KHR_MAINTENANCE_4_EXTENSION_NAME);
    maintenance4.maintenance4 = VK_TRUE;
    maintenance4.pNext = ctx.shaderFloat16 ? static_cast<void*>(&f16) : nullptr;
  }

  VkDeviceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  info.pNext = maintenance4.maintenance4 ? static_cast<void*>(&maintenance4)
                                         : (ctx.shaderFloat16 ? static_cast<void*>(&f16) : nullptr);
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  MB_VK_CHECK(vkCreateDevice(ctx.physical, &info, nullptr, &ctx.device));
  vkGetDeviceQueue(ctx.device, ctx.queueFamily, 0, &ctx.queue);
}

}  // namespace mb::harness
