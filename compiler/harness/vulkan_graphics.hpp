// The harness's graphics path: one render pass that draws an indexed triangle mesh several
// times (one descriptor set and push-constant block per draw) into RGBA32F colour targets
// with a D32 depth buffer, and reads the targets back. The preview (compiler/preview/) draws
// its spheres through it twice with the same vertex shader: once with a permutation's
// fragment shader (docs/fragment-stage.md) and once with an "attributes" fragment shader
// that writes the interpolated inputs, so that the CPU reference shades exactly what the GPU
// shaded (Vulkan's invariance rules: the same vertex shader, state and draws rasterize the
// same fragments with the same interpolated values; Vulkan spec, appendix "Invariance").
//
// Fixed state: triangle list, back faces culled (counter-clockwise front), depth test LESS
// with writes, no blending, one sample per pixel (MSAA off: a pixel is one fragment, whose
// inputs the attributes pass reads back exactly).
#pragma once
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <vector>

#include "harness/vulkan_harness.hpp"

namespace mb::harness {

// A combined image sampler made and owned elsewhere (the environment's cube map and DFG
// LUT); it must stay alive until render() returns.
struct SampledTexture {
  VkImageView view = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
};

struct VertexAttribute {
  uint32_t location = 0;
  uint32_t components = 0;  // floats: 1..4
  uint32_t offset = 0;      // in floats within a vertex
};

struct Mesh {
  std::vector<float> vertices;  // floatsPerVertex floats per vertex
  uint32_t floatsPerVertex = 0;
  std::vector<VertexAttribute> attributes;
  std::vector<uint32_t> indices;  // triangle list, counter-clockwise seen from outside
};

// The resources of one draw's descriptor set 0. Every draw of a job binds the same binding
// numbers with the same types (the set layout is made from the first draw).
struct DrawResources {
  struct Uniform {
    uint32_t binding = 0;
    std::vector<uint8_t> bytes;  // std140 block contents
  };
  struct Texture {
    uint32_t binding = 0;
    SampledTexture texture;
  };
  std::vector<Uniform> uniforms;
  std::vector<Texture> textures;
  std::vector<uint8_t> pushConstants;  // vertex stage, at offset 0
  // Viewport and scissor of this draw: x, y, width, height in pixels; width 0 = the whole
  // target. The preview gives each sphere its own square tile.
  std::array<uint32_t, 4> viewport{0, 0, 0, 0};
};

struct GraphicsJob {
  std::vector<uint32_t> vertexSpirv, fragmentSpirv;  // entry points "main"
  uint32_t width = 0, height = 0;
  uint32_t colorTargets = 1;                      // RGBA32F, fragment outputs 0..n-1
  std::vector<std::array<float, 4>> clearColors;  // per target; missing ones clear to 0
  Mesh mesh;
  std::vector<DrawResources> draws;  // the whole mesh once per entry
  // 0: each texture is a combined image sampler at its binding. Otherwise a sampled image at the
  // binding and its sampler at binding + separateSamplerShift: HLSL's t and s registers, which
  // glslang's HLSL front end (setShiftBinding) and DXC (-fvk-s-shift) place so.
  uint32_t separateSamplerShift = 0;
};

struct GraphicsResult {
  // Per colour target: width * height RGBA pixels, row 0 at the top (Vulkan's framebuffer
  // origin is the upper left).
  std::vector<std::vector<float>> targets;
  double pipelineMs = 0;  // shader modules and pipeline creation (host)
  double renderMs = 0;    // host time from submit to fence (lavapipe rasterizes on the CPU)
};

// Throws HarnessError when the device has no graphics queue or a call fails.
GraphicsResult render(VulkanHarness& gpu, const GraphicsJob& job);

}  // namespace mb::harness
