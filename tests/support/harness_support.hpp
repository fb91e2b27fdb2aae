// Shared by tests that run kernels on the Vulkan harness.
#pragma once
#include <cstdlib>
#include <string>

#include "harness/vulkan_harness.hpp"

namespace mb::harness {

// Default device (lavapipe under CTest), with the validation layer on whenever the test
// environment sets MATBRICKS_VALIDATION (tests/CMakeLists.txt does).
// The GLSL of a compute kernel that follows the harness's contract (harness/vulkan_harness.hpp):
// `extensions` after #version, `declarations` after the record buffers and the push constant,
// then main's `body`, which runs after the `i >= count` return.
inline std::string contractKernel(const std::string& body, const std::string& declarations = "",
                                  const std::string& extensions = "") {
  return "#version 450\n" + extensions +
         "layout(local_size_x = 64) in;\n"
         "layout(std430, set = 0, binding = 0) readonly buffer MbIn { float mbIn[]; };\n"
         "layout(std430, set = 0, binding = 1) writeonly buffer MbOut { float mbOut[]; };\n"
         "layout(push_constant) uniform MbPush { uint count; } mbPush;\n" +
         declarations +
         "void main() {\n"
         "  uint i = gl_GlobalInvocationID.x;\n"
         "  if (i >= mbPush.count) return;\n" +
         body + "}\n";
}

inline DeviceOptions testDeviceOptions() {
  DeviceOptions options;
  options.validation = std::getenv("MATBRICKS_VALIDATION") != nullptr;
  return options;
}

}  // namespace mb::harness
