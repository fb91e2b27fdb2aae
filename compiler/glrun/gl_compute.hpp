// OpenGL 4.5 core and OpenGL ES 3.1 compute on Mesa, headless: a context on EGL's surfaceless
// platform (EGL_MESA_platform_surfaceless), so the GLSL 450 and ESSL 3.10 targets are compiled
// by the driver's own GLSL compiler and run, not only re-parsed by glslang (docs/targets.md
// "Executed"). On a machine without a GPU that is llvmpipe.
//
// Kernel contract: the probe contract of harness/vulkan_harness.hpp as SPIRV-Cross writes it for
// GL (push constants become a std140 uniform block):
//   layout(local_size_x = 64) in;
//   layout(binding = 0, std430) readonly buffer MbIn  { float mbIn[];  };
//   layout(binding = 1, std430) writeonly buffer MbOut { float mbOut[]; };
//   layout(binding = N, std140) uniform MbPush { uint count; } mbPush;
// The uniform block is found by its name (MbPush), whatever its binding.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mb::gl {

// No EGL display or context of the asked API, or a GL call failed. The message is one line.
class GlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class GlApi { Gl45Core, Es31 };
// "OpenGL 4.5 core" or "OpenGL ES 3.1".
std::string apiName(GlApi api);

struct GlRunResult {
  std::vector<float> outputs;  // count * outStride floats
  // Host time from the first upload to the last chunk's read-back: GL ES
  // has no timer queries, so both APIs are timed the same way.
  double ms = 0;
  // The program's compile and link (the driver's GLSL compiler), and its first dispatch (llvmpipe
  // compiles the shader's LLVM code there), on its first run only; 0 later.
  double compileMs = 0;
  double firstDispatchMs = 0;
  uint32_t chunks = 0;
};

class GlCompute {
 public:
  // Throws GlError("no OpenGL ... context ...: why") when EGL or the context is missing.
  explicit GlCompute(GlApi api);
  ~GlCompute();
  GlCompute(const GlCompute&) = delete;
  GlCompute& operator=(const GlCompute&) = delete;

  GlApi api() const { return api_; }
  // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
  std::string deviceName() const;
  bool hasExtension(const std::string& name) const;

  // Compiles (once per distinct source; the program is kept) and runs `count` records.
  // `table`: the kernel's readonly table buffer (binding 2, the harness's kernel contract), when
  // it reads one. Throws GlError with the driver's first compile or link message for a kernel
  // it rejects.
  GlRunResult run(const std::string& source, const std::vector<float>& inputs, uint32_t inStride, uint32_t outStride,
                  uint64_t count, const std::vector<float>* table = nullptr);

 private:
  struct Impl;
  GlApi api_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mb::gl
