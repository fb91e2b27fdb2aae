// compile: the checks that every cross-compiled output passes before it is kept
// (targets.hpp, docs/targets.md "Checks"). Each returns "" when the output passes, else the
// checker's first message.
#pragma once
#include <string>
#include <vector>

#include "compile/spvc_module.hpp"

namespace mb {

// glslang reparses a GLSL compute shader for OpenGL (desktop 450, or ES 310 with `es`),
// generates SPIR-V for OpenGL and runs spirv-val (OpenGL 4.5 rules) on it.
std::string checkGlsl(const std::string& source, bool es);
// glslang's HLSL front end reparses a compute shader (a pixel shader with `pixel`; entry point
// "main"), generates SPIR-V for Vulkan 1.1 and runs spirv-val on it.
std::string checkHlsl(const std::string& source, bool pixel = false);
// No Metal compiler runs on Debian: the kernel entry point and the [[buffer(n)]] index that
// SPIRV-Cross assigned to every buffer and push-constant block must appear in the source.
std::string checkMsl(const std::string& source, const SpvcModule& module);

}  // namespace mb
