// The graphics path (vulkan_graphics.hpp): render pass, framebuffer, pipeline, buffers and
// the one command buffer of a job (the buffers, images and command buffer are the harness's
// shared types, vulkan_resources.hpp), all owned by a GraphicsResources that releases them
// on every exit path, as RunResources does for a compute run.
#include "harness/vulkan_graphics.hpp"

#include <chrono>
#include <cstring>
#include <deque>
#include <optional>

#include "harness/vulkan_check.hpp"
#include "harness/vulkan_internal.hpp"

namespace mb::harness {
namespace {

constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

struct GraphicsResources {
  explicit GraphicsResources(const DeviceContext& ctx) : ctx(ctx), device(ctx.device) {}
  GraphicsResources(const GraphicsResources&) = delete;
  GraphicsResources& operator=(const GraphicsResources&) = delete;
  ~GraphicsResources() {
    commands.reset();  // first: it waits for a submit that we did not see finish
    if (descriptorPool) vkDestroyDescriptorPool(device, descriptorPool, nullptr);
    if (pipeline) vkDestroyPipeline(device, pipeline, nullptr);
    if (pipelineLayout) vkDestroyPipelineLayout(device, pipelineLayout, nullptr);
    if (setLayout) vkDestroyDescriptorSetLayout(device, setLayout, nullptr);
    for (VkShaderModule m : modules) vkDestroyShaderModule(device, m, nullptr);
    if (framebuffer) vkDestroyFramebuffer(device, framebuffer, nullptr);
    if (renderPass) vkDestroyRenderPass(device, renderPass, nullptr);
  }  // the images (after the framebuffer that views them) and buffers release themselves

  const DeviceContext& ctx;
  VkDevice device;
  std::deque<MappedBuffer> buffers;  // vertices, indices, uniforms, read-back (in that order)
  std::deque<DeviceImage> images;    // colour targets, then depth
  VkRenderPass renderPass = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  std::vector<VkShaderModule> modules;
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> sets;
  std::optional<OneShotCommands> commands;
};

// Host-visible, coherent and mapped (vulkan_resources.hpp), filled with `bytes` when given.
MappedBuffer& createBuffer(GraphicsResources& res, uint64_t size, VkBufferUsageFlags usage, const void* bytes) {
  MappedBuffer& b = res.buffers.emplace_back();
  b.create(res.ctx, size, usage);
  if (bytes) std::memcpy(b.mapped, bytes, size);
  return b;
}

void createImage(GraphicsResources& res, const GraphicsJob& job, VkFormat format, VkImageUsageFlags usage,
                 VkImageAspectFlags aspect) {
  VkImageCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {job.width, job.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  res.images.emplace_back().create(res.ctx, info, VK_IMAGE_VIEW_TYPE_2D, aspect);
}

// Colour targets end in TRANSFER_SRC for the copy to the read-back buffer; depth is not kept.
void createRenderPass(GraphicsResources& res, const GraphicsJob& job) {
  std::vector<VkAttachmentDescription> attachments(job.colorTargets + 1);
  std::vector<VkAttachmentReference> colorRefs(job.colorTargets);
  for (uint32_t i = 0; i <= job.colorTargets; ++i) {
    VkAttachmentDescription& a = attachments[i];
    const bool color = i < job.colorTargets;
    a.format = color ? kColorFormat : kDepthFormat;
    a.samples = VK_SAMPLE_COUNT_1_BIT;
    a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    a.storeOp = color ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
    a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    a.finalLayout = color ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    if (color) colorRefs[i] = {i, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  }
  const VkAttachmentReference depthRef{job.colorTargets, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = job.colorTargets;
  subpass.pColorAttachments = colorRefs.data();
  subpass.pDepthStencilAttachment = &depthRef;
  // The colour writes must be done before the copy that follows the pass.
  VkSubpassDependency after{};
  after.srcSubpass = 0;
  after.dstSubpass = VK_SUBPASS_EXTERNAL;
  after.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  after.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  after.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  info.attachmentCount = static_cast<uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &after;
  MB_VK_CHECK(vkCreateRenderPass(res.device, &info, nullptr, &res.renderPass));

  std::vector<VkImageView> views;
  for (const DeviceImage& i : res.images) views.push_back(i.view);
  VkFramebufferCreateInfo fb{};
  fb.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
  fb.renderPass = res.renderPass;
  fb.attachmentCount = static_cast<uint32_t>(views.size());
  fb.pAttachments = views.data();
  fb.width = job.width;
  fb.height = job.height;
  fb.layers = 1;
  MB_VK_CHECK(vkCreateFramebuffer(res.device, &fb, nullptr, &res.framebuffer));
}

VkShaderModule createModule(GraphicsResources& res, const std::vector<uint32_t>& spirv, const char* stage) {
  if (spirv.size() < 5 || spirv[0] != 0x07230203)
    throw HarnessError(std::string("render: the ") + stage + " shader is not a SPIR-V module");
  VkShaderModuleCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  info.codeSize = spirv.size() * sizeof(uint32_t);
  info.pCode = spirv.data();
  VkShaderModule m = VK_NULL_HANDLE;
  MB_VK_CHECK(vkCreateShaderModule(res.device, &info, nullptr, &m));
  res.modules.push_back(m);
  return m;
}

void createLayouts(GraphicsResources& res, const GraphicsJob& job) {
  const DrawResources& first = job.draws.front();
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (const auto& u : first.uniforms)
    bindings.push_back({u.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                        VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  for (const auto& t : first.textures) {
    if (job.separateSamplerShift == 0) {
      bindings.push_back(
          {t.binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
      continue;
    }
    bindings.push_back({t.binding, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
    bindings.push_back(
        {t.binding + job.separateSamplerShift, VK_DESCRIPTOR_TYPE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  }
  VkDescriptorSetLayoutCreateInfo setInfo{};
  setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  setInfo.bindingCount = static_cast<uint32_t>(bindings.size());
  setInfo.pBindings = bindings.data();
  MB_VK_CHECK(vkCreateDescriptorSetLayout(res.device, &setInfo, nullptr, &res.setLayout));

  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, static_cast<uint32_t>(first.pushConstants.size())};
  VkPipelineLayoutCreateInfo layoutInfo{};
  layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &res.setLayout;
  layoutInfo.pushConstantRangeCount = push.size ? 1 : 0;
  layoutInfo.pPushConstantRanges = &push;
  MB_VK_CHECK(vkCreatePipelineLayout(res.device, &layoutInfo, nullptr, &res.pipelineLayout));
}

void createPipeline(GraphicsResources& res, const GraphicsJob& job) {
  VkPipelineShaderStageCreateInfo stages[2]{};
  stages[0].sType = stages[1].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = createModule(res, job.vertexSpirv, "vertex");
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = createModule(res, job.fragmentSpirv, "fragment");
  stages[1].pName = "main";

  const VkVertexInputBindingDescription binding{0, job.mesh.floatsPerVertex * uint32_t{sizeof(float)},
                                                VK_VERTEX_INPUT_RATE_VERTEX};
  static constexpr VkFormat kFloatFormats[4] = {VK_FORMAT_R32_SFLOAT, VK_FORMAT_R32G32_SFLOAT,
                                                VK_FORMAT_R32G32B32_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT};
  std::vector<VkVertexInputAttributeDescription> attributes;
  for (const VertexAttribute& a : job.mesh.attributes)
    attributes.push_back({a.location, 0, kFloatFormats[a.components - 1], a.offset * uint32_t{sizeof(float)}});
  VkPipelineVertexInputStateCreateInfo vertexInput{};
  vertexInput.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
  vertexInput.vertexBindingDescriptionCount = 1;
  vertexInput.pVertexBindingDescriptions = &binding;
  vertexInput.vertexAttributeDescriptionCount = static_cast<uint32_t>(attributes.size());
  vertexInput.pVertexAttributeDescriptions = attributes.data();

  VkPipelineInputAssemblyStateCreateInfo assembly{};
  assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;

  // Set per draw (recordCommands).
  VkPipelineViewportStateCreateInfo viewportState{};
  viewportState.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
  viewportState.viewportCount = 1;
  viewportState.scissorCount = 1;
  const VkDynamicState dynamicStates[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{};
  dynamic.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamicStates;

  VkPipelineRasterizationStateCreateInfo raster{};
  raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_BACK_BIT;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;

  VkPipelineMultisampleStateCreateInfo multisample{};
  multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;

  VkPipelineDepthStencilStateCreateInfo depth{};
  depth.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;

  std::vector<VkPipelineColorBlendAttachmentState> blends(job.colorTargets);
  for (auto& b : blends)
    b.colorWriteMask =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo blend{};
  blend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
  blend.attachmentCount = job.colorTargets;
  blend.pAttachments = blends.data();

  VkGraphicsPipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewportState;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = res.pipelineLayout;
  info.renderPass = res.renderPass;
  info.subpass = 0;
  MB_VK_CHECK(vkCreateGraphicsPipelines(res.device, VK_NULL_HANDLE, 1, &info, nullptr, &res.pipeline));
}

// One set per draw: its uniform blocks in buffers of their own, its textures as given.
void createDescriptorSets(GraphicsResources& res, const GraphicsJob& job) {
  const auto drawCount = static_cast<uint32_t>(job.draws.size());
  std::vector<VkDescriptorPoolSize> sizes;
  const auto& first = job.draws.front();
  if (!first.uniforms.empty())
    sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, static_cast<uint32_t>(first.uniforms.size()) * drawCount});
  const auto textureCount = static_cast<uint32_t>(first.textures.size()) * drawCount;
  if (textureCount && job.separateSamplerShift == 0)
    sizes.push_back({VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, textureCount});
  if (textureCount && job.separateSamplerShift != 0) {
    sizes.push_back({VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, textureCount});
    sizes.push_back({VK_DESCRIPTOR_TYPE_SAMPLER, textureCount});
  }
  VkDescriptorPoolCreateInfo poolInfo{};
  poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  poolInfo.maxSets = drawCount;
  poolInfo.poolSizeCount = static_cast<uint32_t>(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
  MB_VK_CHECK(vkCreateDescriptorPool(res.device, &poolInfo, nullptr, &res.descriptorPool));

  res.sets.resize(drawCount);
  std::vector<VkDescriptorSetLayout> layouts(drawCount, res.setLayout);
  VkDescriptorSetAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  alloc.descriptorPool = res.descriptorPool;
  alloc.descriptorSetCount = drawCount;
  alloc.pSetLayouts = layouts.data();
  MB_VK_CHECK(vkAllocateDescriptorSets(res.device, &alloc, res.sets.data()));

  for (uint32_t d = 0; d < drawCount; ++d) {
    const DrawResources& draw = job.draws[d];
    if (draw.uniforms.size() != first.uniforms.size() || draw.textures.size() != first.textures.size() ||
        draw.pushConstants.size() != first.pushConstants.size())
      throw HarnessError("render: every draw must bind the same resources");
    std::vector<VkDescriptorBufferInfo> bufferInfos(draw.uniforms.size());
    std::vector<VkDescriptorImageInfo> imageInfos(draw.textures.size());
    std::vector<VkWriteDescriptorSet> writes;
    for (size_t u = 0; u < draw.uniforms.size(); ++u) {
      const auto& bytes = draw.uniforms[u].bytes;
      const MappedBuffer& b = createBuffer(res, bytes.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, bytes.data());
      bufferInfos[u] = {b.buffer, 0, bytes.size()};
      VkWriteDescriptorSet& w = writes.emplace_back();
      w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      w.dstSet = res.sets[d];
      w.dstBinding = draw.uniforms[u].binding;
      w.descriptorCount = 1;
      w.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
      w.pBufferInfo = &bufferInfos[u];
    }
    for (size_t t = 0; t < draw.textures.size(); ++t) {
      imageInfos[t] = {draw.textures[t].texture.sampler, draw.textures[t].texture.view,
                       VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
      VkWriteDescriptorSet& w = writes.emplace_back();
      w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      w.dstSet = res.sets[d];
      w.dstBinding = draw.textures[t].binding;
      w.descriptorCount = 1;
      w.descriptorType =
          job.separateSamplerShift ? VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
      w.pImageInfo = &imageInfos[t];
      if (job.separateSamplerShift == 0) continue;
      VkWriteDescriptorSet sampler = w;  // the same image info: a sampler descriptor reads its sampler
      sampler.dstBinding = draw.textures[t].binding + job.separateSamplerShift;
      sampler.descriptorType = VK_DESCRIPTOR_TYPE_SAMPLER;
      writes.push_back(sampler);
    }
    vkUpdateDescriptorSets(res.device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
  }
}

void recordCommands(GraphicsResources& res, const GraphicsJob& job, VkBuffer vertices, VkBuffer indices,
                    VkBuffer readBack) {
  const VkCommandBuffer cmd = res.commands.emplace(res.ctx).cmd();

  std::vector<VkClearValue> clears(job.colorTargets + 1);
  for (uint32_t i = 0; i < job.colorTargets; ++i) {
    std::array<float, 4> c = i < job.clearColors.size() ? job.clearColors[i] : std::array<float, 4>{0, 0, 0, 0};
    std::memcpy(clears[i].color.float32, c.data(), sizeof(float) * 4);
  }
  clears[job.colorTargets].depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo pass{};
  pass.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
  pass.renderPass = res.renderPass;
  pass.framebuffer = res.framebuffer;
  pass.renderArea = {{0, 0}, {job.width, job.height}};
  pass.clearValueCount = static_cast<uint32_t>(clears.size());
  pass.pClearValues = clears.data();
  vkCmdBeginRenderPass(cmd, &pass, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, res.pipeline);
  const VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &zero);
  vkCmdBindIndexBuffer(cmd, indices, 0, VK_INDEX_TYPE_UINT32);
  for (size_t d = 0; d < job.draws.size(); ++d) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, res.pipelineLayout, 0, 1, &res.sets[d], 0, nullptr);
    const auto& area = job.draws[d].viewport;
    const VkRect2D scissor =
        area[2] ? VkRect2D{{static_cast<int32_t>(area[0]), static_cast<int32_t>(area[1])}, {area[2], area[3]}}
                : VkRect2D{{0, 0}, {job.width, job.height}};
    const VkViewport viewport{static_cast<float>(scissor.offset.x),
                              static_cast<float>(scissor.offset.y),
                              static_cast<float>(scissor.extent.width),
                              static_cast<float>(scissor.extent.height),
                              0.0f,
                              1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    const auto& push = job.draws[d].pushConstants;
    if (!push.empty())
      vkCmdPushConstants(cmd, res.pipelineLayout, VK_SHADER_STAGE_VERTEX_BIT, 0, static_cast<uint32_t>(push.size()),
                         push.data());
    vkCmdDrawIndexed(cmd, static_cast<uint32_t>(job.mesh.indices.size()), 1, 0, 0, 0);
  }
  vkCmdEndRenderPass(cmd);

  const VkDeviceSize targetBytes = VkDeviceSize{job.width} * job.height * 4 * sizeof(float);
  for (uint32_t i = 0; i < job.colorTargets; ++i) {
    VkBufferImageCopy copy{};
    copy.bufferOffset = targetBytes * i;
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {job.width, job.height, 1};
    vkCmdCopyImageToBuffer(cmd, res.images[i].image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readBack, 1, &copy);
  }
  VkMemoryBarrier toHost{};
  toHost.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0,
                       nullptr);
}

void checkJob(const DeviceContext& ctx, const GraphicsJob& job) {
  if (!ctx.graphics) throw HarnessError("render: the device's queue has no graphics support");
  if (job.width == 0 || job.height == 0 || job.colorTargets == 0 || job.draws.empty() || job.mesh.indices.empty() ||
      job.mesh.floatsPerVertex == 0)
    throw HarnessError("render: empty job (no pixels, targets, draws or triangles)");
  const auto& limits = ctx.props.limits;
  if (job.width > limits.maxFramebufferWidth || job.height > limits.maxFramebufferHeight)
    throw HarnessError("render: " + std::to_string(job.width) + "x" + std::to_string(job.height) +
                       " exceeds the device's framebuffer limit");
  if (job.colorTargets > limits.maxColorAttachments)
    throw HarnessError("render: more colour targets than the device's maxColorAttachments");
  if (job.draws.front().pushConstants.size() > limits.maxPushConstantsSize)
    throw HarnessError("render: push constants exceed the device's maxPushConstantsSize");
}

}  // namespace

GraphicsResult render(VulkanHarness& gpu, const GraphicsJob& job) {
  const std::shared_ptr<DeviceContext> ctx = gpu.context();
  checkJob(*ctx, job);
  GraphicsResult result;
  GraphicsResources res(*ctx);
  for (uint32_t i = 0; i < job.colorTargets; ++i)
    createImage(res, job, kColorFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                VK_IMAGE_ASPECT_COLOR_BIT);
  createImage(res, job, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);
  createRenderPass(res, job);
  const auto t0 = std::chrono::steady_clock::now();
  createLayouts(res, job);
  createPipeline(res, job);
  result.pipelineMs = msSince(t0);

  const VkBuffer vertexBuffer = createBuffer(res, job.mesh.vertices.size() * sizeof(float),
                                             VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, job.mesh.vertices.data())
                                    .buffer;
  const VkBuffer indexBuffer = createBuffer(res, job.mesh.indices.size() * sizeof(uint32_t),
                                            VK_BUFFER_USAGE_INDEX_BUFFER_BIT, job.mesh.indices.data())
                                   .buffer;
  createDescriptorSets(res, job);
  const size_t targetFloats = size_t{job.width} * job.height * 4;
  const MappedBuffer& readBack =
      createBuffer(res, targetFloats * sizeof(float) * job.colorTargets, VK_BUFFER_USAGE_TRANSFER_DST_BIT, nullptr);
  recordCommands(res, job, vertexBuffer, indexBuffer, readBack.buffer);

  result.renderMs = res.commands->submitAndWait("render: the draws");
  const auto* pixels = static_cast<const float*>(readBack.mapped);
  for (uint32_t i = 0; i < job.colorTargets; ++i)
    result.targets.emplace_back(pixels + targetFloats * i, pixels + targetFloats * (i + 1));
  return result;
}

}  // namespace mb::harness
