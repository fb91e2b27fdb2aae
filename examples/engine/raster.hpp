// examples/engine: the raster path. Draws a mesh with a vertex shader (the reference
// shaderlib/common/engine_vertex.vert, compiled by this example's build) and a package
// permutation's fragment shader (docs/fragment-stage.md) into an RGBA32F target with depth,
// and reads the target back. Knows nothing about a particular package: the parameter and
// frame blocks arrive as bytes filled from the generated header's structs.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "gpu.hpp"

namespace engine {

// The reference vertex shader's inputs, locations 0-3.
struct Vertex {
  float position[3];
  float normal[3];
  float tangent[4];  // xyz: direction of increasing u; w: handedness
  float uv[2];
};

struct Mesh {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;
};

// A unit UV sphere at the origin; u = 0 faces +z. Vertices lie on the sphere, so the mesh is
// inscribed in it; the triangles that collapse at the poles are left out.
inline Mesh uvSphere(int stacks, int slices) {
  const float pi = 3.14159265358979f;
  Mesh m;
  for (int i = 0; i <= stacks; ++i)
    for (int j = 0; j <= slices; ++j) {
      const float theta = pi * i / stacks, phi = 2.0f * pi * j / slices;
      const float p[3] = {std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)};
      m.vertices.push_back({{p[0], p[1], p[2]},
                            {p[0], p[1], p[2]},
                            {std::cos(phi), 0.0f, -std::sin(phi), 1.0f},
                            {float(j) / slices, float(i) / stacks}});
    }
  for (int i = 0; i < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      const uint32_t a = i * (slices + 1) + j, b = a + slices + 1;
      if (i > 0) m.indices.insert(m.indices.end(), {a, b, a + 1});
      if (i < stacks - 1) m.indices.insert(m.indices.end(), {a + 1, b, b + 1});
    }
  return m;
}

// What one draw needs: SPIR-V of both stages, the push constants of engine_vertex.vert
// (column-major model and viewProjection), the std140 blocks at bindings 0 and 1 of set 0
// (params empty when the permutation has no parameter block), and the square target's size.
struct DrawSpec {
  std::vector<uint32_t> vertexSpirv, fragmentSpirv;
  float pushConstants[32];
  std::vector<unsigned char> params, frame;
  uint32_t size;
};

struct Attachment {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
};

inline Attachment attachment(Gpu& gpu, VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect,
                             uint32_t size) {
  Attachment a;
  auto ici = info<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  ici.imageType = VK_IMAGE_TYPE_2D;
  ici.format = format;
  ici.extent = {size, size, 1};
  ici.mipLevels = 1;
  ici.arrayLayers = 1;
  ici.samples = VK_SAMPLE_COUNT_1_BIT;
  ici.tiling = VK_IMAGE_TILING_OPTIMAL;
  ici.usage = usage;
  ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  check(vkCreateImage(gpu.device(), &ici, nullptr, &a.image), "vkCreateImage");
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(gpu.device(), a.image, &req);
  a.memory = gpu.allocate(req, 0);
  check(vkBindImageMemory(gpu.device(), a.image, a.memory, 0), "vkBindImageMemory");
  auto ivci = info<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
  ivci.image = a.image;
  ivci.viewType = VK_IMAGE_VIEW_TYPE_2D;
  ivci.format = format;
  ivci.subresourceRange = {aspect, 0, 1, 0, 1};
  check(vkCreateImageView(gpu.device(), &ivci, nullptr, &a.view), "vkCreateImageView");
  return a;
}

inline void release(Gpu& gpu, Attachment& a) {
  vkDestroyImageView(gpu.device(), a.view, nullptr);
  vkDestroyImage(gpu.device(), a.image, nullptr);
  vkFreeMemory(gpu.device(), a.memory, nullptr);
}

constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;  // colour attachment support is mandatory
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

// Colour cleared to 0 and kept (then copied out), depth cleared to 1 and discarded.
inline VkRenderPass renderPass(Gpu& gpu) {
  VkAttachmentDescription attachments[2] = {};
  attachments[0].format = kColorFormat;
  attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
  attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  attachments[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  attachments[1] = attachments[0];
  attachments[1].format = kDepthFormat;
  attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  VkAttachmentReference color{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depth{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color;
  subpass.pDepthStencilAttachment = &depth;
  // The copy after the pass reads what the subpass wrote (and the layout transition to
  // TRANSFER_SRC happens between them).
  VkSubpassDependency dependency{};
  dependency.srcSubpass = 0;
  dependency.dstSubpass = VK_SUBPASS_EXTERNAL;
  dependency.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependency.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependency.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependency.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  auto rpci = info<VkRenderPassCreateInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO);
  rpci.attachmentCount = 2;
  rpci.pAttachments = attachments;
  rpci.subpassCount = 1;
  rpci.pSubpasses = &subpass;
  rpci.dependencyCount = 1;
  rpci.pDependencies = &dependency;
  VkRenderPass pass;
  check(vkCreateRenderPass(gpu.device(), &rpci, nullptr, &pass), "vkCreateRenderPass");
  return pass;
}

// The fixed-function state of an opaque, depth-tested, unculled triangle list into the
// whole square target.
inline VkPipeline graphicsPipeline(Gpu& gpu, VkShaderModule vertex, VkShaderModule fragment, VkPipelineLayout layout,
                                   VkRenderPass pass, uint32_t size) {
  VkPipelineShaderStageCreateInfo stages[2];
  for (int i = 0; i < 2; ++i) {
    stages[i] = info<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
    stages[i].stage = i == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[i].module = i == 0 ? vertex : fragment;
    stages[i].pName = "main";
  }
  VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
  const VkVertexInputAttributeDescription attributes[4] = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
      {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(Vertex, tangent)},
      {3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(Vertex, uv)}};
  auto vertexInput =
      info<VkPipelineVertexInputStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
  vertexInput.vertexBindingDescriptionCount = 1;
  vertexInput.pVertexBindingDescriptions = &binding;
  vertexInput.vertexAttributeDescriptionCount = 4;
  vertexInput.pVertexAttributeDescriptions = attributes;
  auto assembly =
      info<VkPipelineInputAssemblyStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkViewport viewport{0.0f, 0.0f, float(size), float(size), 0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, {size, size}};
  auto viewportState = info<VkPipelineViewportStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
  viewportState.viewportCount = 1;
  viewportState.pViewports = &viewport;
  viewportState.scissorCount = 1;
  viewportState.pScissors = &scissor;
  auto raster =
      info<VkPipelineRasterizationStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  auto multisample =
      info<VkPipelineMultisampleStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  auto depth = info<VkPipelineDepthStencilStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;
  VkPipelineColorBlendAttachmentState blendAttachment{};
  blendAttachment.colorWriteMask =
      VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  auto blend = info<VkPipelineColorBlendStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
  blend.attachmentCount = 1;
  blend.pAttachments = &blendAttachment;
  auto gpci = info<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
  gpci.stageCount = 2;
  gpci.pStages = stages;
  gpci.pVertexInputState = &vertexInput;
  gpci.pInputAssemblyState = &assembly;
  gpci.pViewportState = &viewportState;
  gpci.pRasterizationState = &raster;
  gpci.pMultisampleState = &multisample;
  gpci.pDepthStencilState = &depth;
  gpci.pColorBlendState = &blend;
  gpci.layout = layout;
  gpci.renderPass = pass;
  VkPipeline pipeline;
  check(vkCreateGraphicsPipelines(gpu.device(), VK_NULL_HANDLE, 1, &gpci, nullptr, &pipeline),
        "vkCreateGraphicsPipelines");
  return pipeline;
}

// Draws `mesh` as `spec` says and returns the target's RGBA floats, row by row from the top.
inline std::vector<float> draw(Gpu& gpu, const Mesh& mesh, const DrawSpec& spec) {
  VkDevice device = gpu.device();
  const uint32_t size = spec.size;
  Attachment color =
      attachment(gpu, kColorFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                 VK_IMAGE_ASPECT_COLOR_BIT, size);
  Attachment depth =
      attachment(gpu, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT, size);
  VkRenderPass pass = renderPass(gpu);
  VkImageView views[2] = {color.view, depth.view};
  auto fci = info<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO);
  fci.renderPass = pass;
  fci.attachmentCount = 2;
  fci.pAttachments = views;
  fci.width = size;
  fci.height = size;
  fci.layers = 1;
  VkFramebuffer framebuffer;
  check(vkCreateFramebuffer(device, &fci, nullptr, &framebuffer), "vkCreateFramebuffer");

  // Set 0: the parameter block at binding 0 (when there is one) and the frame block at 1.
  Buffer frame = gpu.buffer(spec.frame.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  std::memcpy(frame.mapped, spec.frame.data(), spec.frame.size());
  Buffer params;
  if (!spec.params.empty()) {
    params = gpu.buffer(spec.params.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memcpy(params.mapped, spec.params.data(), spec.params.size());
  }
  VkDescriptorSetLayoutBinding bindings[2] = {};
  Buffer* buffers[2] = {&frame, &params};
  for (uint32_t i = 0; i < 2; ++i) {
    bindings[i].binding = 1 - i;
    bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    bindings[i].descriptorCount = 1;
    bindings[i].stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
  }
  const uint32_t bindingCount = spec.params.empty() ? 1 : 2;
  auto dslci = info<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  dslci.bindingCount = bindingCount;
  dslci.pBindings = bindings;
  VkDescriptorSetLayout setLayout;
  check(vkCreateDescriptorSetLayout(device, &dslci, nullptr, &setLayout), "vkCreateDescriptorSetLayout");
  VkDescriptorPool descriptorPool;
  VkDescriptorSet set = gpu.bufferSet(setLayout, bindings, buffers, bindingCount, descriptorPool);
  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof spec.pushConstants};
  auto plci = info<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  plci.setLayoutCount = 1;
  plci.pSetLayouts = &setLayout;
  plci.pushConstantRangeCount = 1;
  plci.pPushConstantRanges = &push;
  VkPipelineLayout layout;
  check(vkCreatePipelineLayout(device, &plci, nullptr, &layout), "vkCreatePipelineLayout");
  VkShaderModule vertexModule = gpu.shaderModule(spec.vertexSpirv);
  VkShaderModule fragmentModule = gpu.shaderModule(spec.fragmentSpirv);
  VkPipeline pipeline = graphicsPipeline(gpu, vertexModule, fragmentModule, layout, pass, size);

  Buffer vertices = gpu.buffer(sizeof(Vertex) * mesh.vertices.size(), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  std::memcpy(vertices.mapped, mesh.vertices.data(), vertices.size);
  Buffer indices = gpu.buffer(sizeof(uint32_t) * mesh.indices.size(), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  std::memcpy(indices.mapped, mesh.indices.data(), indices.size);
  Buffer readback = gpu.buffer(sizeof(float) * 4 * size * size, VK_BUFFER_USAGE_TRANSFER_DST_BIT);

  gpu.submit([&](VkCommandBuffer cmd) {
    VkClearValue clears[2] = {};
    clears[1].depthStencil = {1.0f, 0};
    auto begin = info<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
    begin.renderPass = pass;
    begin.framebuffer = framebuffer;
    begin.renderArea = {{0, 0}, {size, size}};
    begin.clearValueCount = 2;
    begin.pClearValues = clears;
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof spec.pushConstants, spec.pushConstants);
    VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertices.buffer, &offset);
    vkCmdBindIndexBuffer(cmd, indices.buffer, 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, static_cast<uint32_t>(mesh.indices.size()), 1, 0, 0, 0);
    vkCmdEndRenderPass(cmd);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {size, size, 1};
    vkCmdCopyImageToBuffer(cmd, color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &region);
    auto barrier = info<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr, 0,
                         nullptr);
  });
  const float* texels = static_cast<const float*>(readback.mapped);
  std::vector<float> rgba(texels, texels + 4 * size * size);

  gpu.release(readback);
  gpu.release(indices);
  gpu.release(vertices);
  vkDestroyPipeline(device, pipeline, nullptr);
  vkDestroyShaderModule(device, fragmentModule, nullptr);
  vkDestroyShaderModule(device, vertexModule, nullptr);
  vkDestroyPipelineLayout(device, layout, nullptr);
  vkDestroyDescriptorPool(device, descriptorPool, nullptr);
  vkDestroyDescriptorSetLayout(device, setLayout, nullptr);
  if (!spec.params.empty()) gpu.release(params);
  gpu.release(frame);
  vkDestroyFramebuffer(device, framebuffer, nullptr);
  vkDestroyRenderPass(device, pass, nullptr);
  release(gpu, depth);
  release(gpu, color);
  return rgba;
}

}  // namespace engine
