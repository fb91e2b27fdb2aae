// examples/engine: a minimal engine consuming a matbricks package (docs/package.md). It
// includes the generated header, refuses at compile time to build without the permutations
// it uses, loads their SPIR-V, fills the std140 parameter block from the generated struct and
// the shading records from the generated record layout, shades a 32x32 lit sphere on the
// Vulkan device, writes engine_<material>.ppm next to the binary, and checks the pixels.
// Plain Vulkan 1.1, no matbricks library: this is what an outside engine would write.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine_materials.hpp"

namespace em = engine_materials;

// A permutation this engine needs but the package lacks is a build error, never a fallback.
constexpr std::string_view kMetalKey = "ue4_metal.standard.dir.none.fp32";
constexpr std::string_view kPlasticKey = "filament_plastic.standard.dir.none.fp32";
static_assert(em::hasPermutation(kMetalKey) && em::hasPermutation(kPlasticKey),
              "the package lacks a permutation this engine uses");
constexpr const em::Permutation* kMetal = em::findPermutation(kMetalKey);
constexpr const em::Permutation* kPlastic = em::findPermutation(kPlasticKey);
// This engine fills n, v and l only: refuse a record layout that asks for more.
static_assert(kMetal->inputCount == 3 && kPlastic->inputCount == 3, "unexpected shading record inputs");
static_assert(em::recordOffset(*kPlastic, "l") != ~0u, "records without a light direction");
static_assert(kPlastic->paramsSize <= sizeof(em::filament_plastic_Params), "parameter struct too small");

namespace {

constexpr int kSize = 32;
int gValidationMessages = 0;

// A zeroed Vulkan info struct with its sType set.
template <class T>
T info(VkStructureType type) {
  T t{};
  t.sType = type;
  return t;
}

void check(VkResult r, const char* what) {
  if (r != VK_SUCCESS) throw std::runtime_error(std::string(what) + " failed (VkResult " + std::to_string(r) + ")");
}

VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                         VkDebugUtilsMessageTypeFlagsEXT,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
    std::fprintf(stderr, "validation: %s\n", data->pMessage);
    ++gValidationMessages;
  }
  return VK_FALSE;
}

struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
  VkDeviceSize size = 0;
};

class Gpu {
 public:
  Gpu() {
    bool layer = hasLayer("VK_LAYER_KHRONOS_validation");
    const char* layers[] = {"VK_LAYER_KHRONOS_validation"};
    const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
    auto app = info<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.pApplicationName = "matbricks engine example";
    app.apiVersion = VK_API_VERSION_1_1;
    auto ici = info<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    ici.pApplicationInfo = &app;
    ici.enabledLayerCount = layer ? 1 : 0;
    ici.ppEnabledLayerNames = layers;
    ici.enabledExtensionCount = layer ? 1 : 0;
    ici.ppEnabledExtensionNames = extensions;
    check(vkCreateInstance(&ici, nullptr, &instance_), "vkCreateInstance");
    if (layer) {
      auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
      auto mci = info<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
      mci.messageSeverity =
          VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
      mci.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                        VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
      mci.pfnUserCallback = onMessage;
      if (create) check(create(instance_, &mci, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
    }
    std::printf("validation layer: %s\n", layer ? "on" : "not installed");
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance_, &count, nullptr);
    if (count == 0) throw std::runtime_error("no Vulkan device");
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance_, &count, devices.data());
    physical_ = devices[0];
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(physical_, &props);
    std::printf("device: %s\n", props.deviceName);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, families.data());
    family_ = count;
    for (uint32_t i = 0; i < count && family_ == count; ++i)
      if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) family_ = i;
    if (family_ == count) throw std::runtime_error("no compute queue");
    float priority = 1.0f;
    auto qci = info<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    qci.queueFamilyIndex = family_;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    auto dci = info<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    check(vkCreateDevice(physical_, &dci, nullptr, &device_), "vkCreateDevice");
    vkGetDeviceQueue(device_, family_, 0, &queue_);
    auto pci = info<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    pci.queueFamilyIndex = family_;
    check(vkCreateCommandPool(device_, &pci, nullptr, &pool_), "vkCreateCommandPool");
  }
  ~Gpu() {
    vkDestroyCommandPool(device_, pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
    if (messenger_) {
      auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
      if (destroy) destroy(instance_, messenger_, nullptr);
    }
    vkDestroyInstance(instance_, nullptr);
  }
  Gpu(const Gpu&) = delete;
  Gpu& operator=(const Gpu&) = delete;

  Buffer buffer(VkDeviceSize size, VkBufferUsageFlags usage) {
    Buffer b;
    b.size = size;
    auto bci = info<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    bci.size = size;
    bci.usage = usage;
    check(vkCreateBuffer(device_, &bci, nullptr, &b.buffer), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, b.buffer, &req);
    VkPhysicalDeviceMemoryProperties mem;
    vkGetPhysicalDeviceMemoryProperties(physical_, &mem);
    const VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    uint32_t type = mem.memoryTypeCount;
    for (uint32_t i = 0; i < mem.memoryTypeCount && type == mem.memoryTypeCount; ++i)
      if ((req.memoryTypeBits & (1u << i)) && (mem.memoryTypes[i].propertyFlags & want) == want) type = i;
    if (type == mem.memoryTypeCount) throw std::runtime_error("no host-visible coherent memory");
    auto mai = info<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    mai.allocationSize = req.size;
    mai.memoryTypeIndex = type;
    check(vkAllocateMemory(device_, &mai, nullptr, &b.memory), "vkAllocateMemory");
    check(vkBindBufferMemory(device_, b.buffer, b.memory, 0), "vkBindBufferMemory");
    check(vkMapMemory(device_, b.memory, 0, size, 0, &b.mapped), "vkMapMemory");
    return b;
  }
  void release(Buffer& b) {
    vkUnmapMemory(device_, b.memory);
    vkDestroyBuffer(device_, b.buffer, nullptr);
    vkFreeMemory(device_, b.memory, nullptr);
  }

  // Runs the package's kernel ABI (docs/package.md "Kernel ABI"): records at binding 0,
  // results at binding 1, the std140 parameter block at binding 2, the count as push constant.
  void run(const std::vector<uint32_t>& spirv, Buffer& records, Buffer& results, Buffer* params, uint32_t count) {
    auto smci = info<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    smci.codeSize = spirv.size() * 4;
    smci.pCode = spirv.data();
    VkShaderModule module;
    check(vkCreateShaderModule(device_, &smci, nullptr, &module), "vkCreateShaderModule");
    VkDescriptorSetLayoutBinding bindings[3] = {};
    for (uint32_t i = 0; i < 3; ++i) {
      bindings[i].binding = i;
      bindings[i].descriptorType = i == 2 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      bindings[i].descriptorCount = 1;
      bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    const uint32_t bindingCount = params ? 3 : 2;
    auto dslci = info<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    dslci.bindingCount = bindingCount;
    dslci.pBindings = bindings;
    VkDescriptorSetLayout setLayout;
    check(vkCreateDescriptorSetLayout(device_, &dslci, nullptr, &setLayout), "vkCreateDescriptorSetLayout");
    VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(uint32_t)};
    auto plci = info<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &setLayout;
    plci.pushConstantRangeCount = 1;
    plci.pPushConstantRanges = &push;
    VkPipelineLayout pipelineLayout;
    check(vkCreatePipelineLayout(device_, &plci, nullptr, &pipelineLayout), "vkCreatePipelineLayout");
    auto cpci = info<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
    cpci.stage = info<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
    cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    cpci.stage.module = module;
    cpci.stage.pName = "main";
    cpci.layout = pipelineLayout;
    VkPipeline pipeline;
    check(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &cpci, nullptr, &pipeline), "vkCreateComputePipelines");

    VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2}, {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1}};
    auto dpci = info<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    dpci.maxSets = 1;
    dpci.poolSizeCount = 2;
    dpci.pPoolSizes = sizes;
    VkDescriptorPool descriptorPool;
    check(vkCreateDescriptorPool(device_, &dpci, nullptr, &descriptorPool), "vkCreateDescriptorPool");
    auto dsai = info<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    dsai.descriptorPool = descriptorPool;
    dsai.descriptorSetCount = 1;
    dsai.pSetLayouts = &setLayout;
    VkDescriptorSet set;
    check(vkAllocateDescriptorSets(device_, &dsai, &set), "vkAllocateDescriptorSets");
    Buffer* buffers[3] = {&records, &results, params};
    VkDescriptorBufferInfo infos[3];
    VkWriteDescriptorSet writes[3];
    for (uint32_t i = 0; i < bindingCount; ++i) {
      infos[i] = {buffers[i]->buffer, 0, buffers[i]->size};
      writes[i] = info<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
      writes[i].dstSet = set;
      writes[i].dstBinding = i;
      writes[i].descriptorCount = 1;
      writes[i].descriptorType = bindings[i].descriptorType;
      writes[i].pBufferInfo = &infos[i];
    }
    vkUpdateDescriptorSets(device_, bindingCount, writes, 0, nullptr);

    auto cbai = info<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    cbai.commandPool = pool_;
    cbai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cbai.commandBufferCount = 1;
    VkCommandBuffer cmd;
    check(vkAllocateCommandBuffers(device_, &cbai, &cmd), "vkAllocateCommandBuffers");
    auto begin = info<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(count), &count);
    vkCmdDispatch(cmd, (count + 63) / 64, 1, 1);  // the kernel's local_size_x is 64
    auto barrier = info<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0,
                         nullptr, 0, nullptr);
    check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    auto submit = info<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    check(vkQueueSubmit(queue_, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
    check(vkQueueWaitIdle(queue_), "vkQueueWaitIdle");

    vkFreeCommandBuffers(device_, pool_, 1, &cmd);
    vkDestroyDescriptorPool(device_, descriptorPool, nullptr);
    vkDestroyPipeline(device_, pipeline, nullptr);
    vkDestroyPipelineLayout(device_, pipelineLayout, nullptr);
    vkDestroyDescriptorSetLayout(device_, setLayout, nullptr);
    vkDestroyShaderModule(device_, module, nullptr);
  }

 private:
  static bool hasLayer(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    for (const auto& l : layers)
      if (std::strcmp(l.layerName, name) == 0) return true;
    return false;
  }
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  uint32_t family_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
};

std::vector<uint32_t> loadSpirv(const em::Permutation& p) {
  const std::string path = std::string(MATBRICKS_PACKAGE_DIR) + "/" + std::string(p.spirv);
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<uint32_t> words(static_cast<size_t>(in.tellg()) / 4);
  in.seekg(0);
  in.read(reinterpret_cast<char*>(words.data()), static_cast<std::streamsize>(words.size() * 4));
  return words;
}

struct Image {
  std::vector<float> rgb = std::vector<float>(kSize * kSize * 3, 0.0f);
};

// One record per pixel covered by a unit sphere seen head-on: n from the sphere, v toward
// the camera, one directional light from the upper left.
Image shadeSphere(Gpu& gpu, const em::Permutation& p, const void* params, size_t paramsBytes) {
  std::vector<int> pixels;
  Buffer records = gpu.buffer(sizeof(float) * p.recordStride * kSize * kSize, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  float* rec = static_cast<float*>(records.mapped);
  const float l[3] = {-0.408248f, 0.408248f, 0.816497f};
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float sx = (x + 0.5f) / kSize * 2.0f - 1.0f, sy = 1.0f - (y + 0.5f) / kSize * 2.0f;
      const float r2 = sx * sx + sy * sy;
      if (r2 >= 1.0f) continue;
      float* r = rec + pixels.size() * p.recordStride;
      const float n[3] = {sx, sy, std::sqrt(1.0f - r2)}, v[3] = {0.0f, 0.0f, 1.0f};
      std::memcpy(r + em::recordOffset(p, "n"), n, sizeof n);
      std::memcpy(r + em::recordOffset(p, "v"), v, sizeof v);
      std::memcpy(r + em::recordOffset(p, "l"), l, sizeof l);
      pixels.push_back(y * kSize + x);
    }
  const uint32_t count = static_cast<uint32_t>(pixels.size());
  Buffer results = gpu.buffer(sizeof(float) * p.resultStride * count, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  Buffer block;
  if (p.paramsSize) {
    block = gpu.buffer(paramsBytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memcpy(block.mapped, params, paramsBytes);
  }
  gpu.run(loadSpirv(p), records, results, p.paramsSize ? &block : nullptr, count);
  Image img;
  const float* out = static_cast<const float*>(results.mapped);
  for (uint32_t i = 0; i < count; ++i)
    for (int c = 0; c < 3; ++c) img.rgb[pixels[i] * 3 + c] = out[i * p.resultStride + c];
  gpu.release(records);
  gpu.release(results);
  if (p.paramsSize) gpu.release(block);
  return img;
}

int gFailures = 0;
void expect(bool ok, const std::string& what) {
  std::printf("%s %s\n", ok ? "ok  " : "FAIL", what.c_str());
  gFailures += ok ? 0 : 1;
}

void checkImage(const Image& img, const std::string& name) {
  bool finite = true;
  float lo = img.rgb[0], hi = img.rgb[0];
  for (float v : img.rgb) {
    finite = finite && std::isfinite(v) && v >= 0.0f;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  expect(finite, name + ": every value finite and non-negative");
  expect(hi - lo > 1e-3f,
         name + ": the image is not constant (range " + std::to_string(lo) + " .. " + std::to_string(hi) + ")");
}

// Reinhard-tonemapped, gamma 2.2, binary PPM.
void writePpm(const Image& img, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << kSize << " " << kSize << "\n255\n";
  for (float v : img.rgb) {
    const float t = std::pow(v / (1.0f + v), 1.0f / 2.2f);
    out.put(static_cast<char>(static_cast<unsigned char>(std::lround(std::clamp(t, 0.0f, 1.0f) * 255.0f))));
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace

int main(int, char** argv) {
  try {
    std::string dir = argv[0];
    dir = dir.find('/') == std::string::npos ? "." : dir.substr(0, dir.rfind('/'));
    Gpu gpu;

    em::ue4_metal_Params metal{};
    metal.roughness = 0.3f;
    const Image metalImage = shadeSphere(gpu, *kMetal, &metal, sizeof metal);
    checkImage(metalImage, "ue4_metal");
    writePpm(metalImage, dir + "/engine_ue4_metal.ppm");

    em::filament_plastic_Params plastic{};
    const float red[3] = {0.8f, 0.1f, 0.1f};
    std::memcpy(plastic.baseColor, red, sizeof red);
    plastic.metallic = 0.0f;
    plastic.roughness = 0.4f;
    const Image smooth = shadeSphere(gpu, *kPlastic, &plastic, sizeof plastic);
    checkImage(smooth, "filament_plastic");
    writePpm(smooth, dir + "/engine_filament_plastic.ppm");

    // The parameter block is live: a rougher plastic must shade differently.
    plastic.roughness = 0.9f;
    const Image rough = shadeSphere(gpu, *kPlastic, &plastic, sizeof plastic);
    checkImage(rough, "filament_plastic rough");
    float diff = 0.0f;
    for (size_t i = 0; i < rough.rgb.size(); ++i) diff = std::max(diff, std::fabs(rough.rgb[i] - smooth.rgb[i]));
    expect(diff > 1e-3f, "roughness 0.4 -> 0.9 changes the image (max difference " + std::to_string(diff) + ")");
    // And red stays red: the block's vec3 baseColor and the float after it are read where the
    // struct put them (a std140 mismatch would mix the channels).
    double sum[3] = {0, 0, 0};
    for (size_t i = 0; i < smooth.rgb.size(); ++i) sum[i % 3] += smooth.rgb[i];
    expect(sum[0] > 2.0 * sum[1] && sum[0] > 2.0 * sum[2], "the red plastic is red");
    writePpm(rough, dir + "/engine_filament_plastic_rough.ppm");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "engine example: %s\n", e.what());
    return 1;
  }
  expect(gValidationMessages == 0, "no validation messages (" + std::to_string(gValidationMessages) + ")");
  return gFailures == 0 ? 0 : 1;
}
