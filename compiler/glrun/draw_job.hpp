// A draw described for the GL-family APIs, which bind by name: OpenGL 4.5 and OpenGL ES 3.1 on
// EGL (gl_draw.hpp) and WebGL 2.0 in a browser (compiler/webgl/). The preview's two passes
// (docs/preview.md) go through it for the glsl450, essl310 and webgl2 targets, as they go through
// harness/vulkan_graphics.hpp for SPIR-V. Everything is CPU data: the textures' texels, the
// uniform blocks' std140 bytes, the mesh.
//
// Fixed state, the same as the Vulkan path's: triangle list, back faces culled, depth test LESS
// with writes (depth cleared to 1), no blending, no multisampling. The vertex shader's clip space
// is Vulkan's (y down, depth 0..1): the rows GL's glReadPixels returns bottom-up then hold what
// Vulkan's framebuffer holds top-down, so results[t] row 0 is the same pixel row as the Vulkan
// path's row 0. The window coordinates are the same numbers in both APIs, but their facing
// formulas differ in sign (Vulkan spec "Basic Polygon Rasterization": a = -1/2 sum(...); OpenGL
// 4.5 and ES 3.0 section 14.6.1 / 3.6.1: a = +1/2 sum(...)), so the mesh's counter-clockwise
// front in Vulkan is glFrontFace(GL_CW) here.
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace mb::gl {

struct DrawTextureLevel {
  uint32_t width = 0, height = 0;
  std::vector<float> rgba;  // width * height texels (per face for a cube), row 0 first
};

// An RGBA32F texture with linear min/mag/mip filtering and clamp-to-edge wrapping (the
// Vulkan path's sampler, harness/gpu_texture.hpp); a cube's levels hold the six faces in
// +X, -X, +Y, -Y, +Z, -Z order, each width * height texels (preview/environment.hpp CubeLevel).
struct DrawTexture {
  bool cube = false;
  std::vector<DrawTextureLevel> levels;  // the full chain a cube is filtered through, or one level
};

struct DrawVertexAttribute {
  uint32_t location = 0;    // the vertex shader's layout(location)
  uint32_t components = 0;  // floats: 1..4
  uint32_t offset = 0;      // in floats within a vertex
};

struct DrawMesh {
  std::vector<float> vertices;  // floatsPerVertex floats per vertex
  uint32_t floatsPerVertex = 0;
  std::vector<DrawVertexAttribute> attributes;
  std::vector<uint32_t> indices;  // triangle list, counter-clockwise seen from outside
};

struct DrawCall {
  // std140 uniform block contents by block name (e.g. "MbFrameBlock", "MbVertexPush"). A block
  // that no stage of the program declares is skipped: an optimized fragment shader may drop
  // one it never reads.
  std::map<std::string, std::vector<uint8_t>> uniformBlocks;
  // Sampler uniform name -> index into DrawJob::textures; skipped, as above, when the program
  // has no such uniform.
  std::map<std::string, size_t> samplers;
  std::array<uint32_t, 4> viewport{0, 0, 0, 0};  // x, y (from row 0), width, height; width 0: whole
};

struct DrawJob {
  std::string vertexSource, fragmentSource;  // complete shaders, #version line first
  uint32_t width = 0, height = 0;
  uint32_t colorTargets = 1;                      // RGBA32F, fragment outputs 0..n-1
  std::vector<std::array<float, 4>> clearColors;  // per target; missing ones clear to 0
  DrawMesh mesh;
  std::vector<DrawTexture> textures;
  std::vector<DrawCall> draws;  // the whole mesh once per entry, in order
};

struct DrawResult {
  // Per colour target: width * height RGBA floats, row 0 = the Vulkan path's row 0 (above).
  std::vector<std::vector<float>> targets;
  std::string device;    // the renderer, e.g. GL_RENDERER and GL_VERSION
  double compileMs = 0;  // the driver's compile and link of the program
  double renderMs = 0;   // uploads, draws and read-back (host time)
};

}  // namespace mb::gl
