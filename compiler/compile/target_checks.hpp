// compile: the checks that every cross-compiled output passes before it is kept
// (targets.hpp, docs/targets.md "Checks"). Each returns "" when the output passes, else the
// checker's first message.
#pragma once
#include <string>
#include <vector>

#include "compile/glsl_compiler.hpp"
#include "compile/spvc_module.hpp"

namespace mb {

// glslang reparses a GLSL shader of `stage` for OpenGL (desktop
// 450, or ES 310 with `es`), generates SPIR-V for OpenGL and runs spirv-val (OpenGL 4.5 rules).
std::string checkGlsl(const std::string& source, bool es, ShaderStage stage = ShaderStage::Compute);
// WebGL 2.0's ESSL 3.00 vertex or fragment shader: glslang parses and links it as ESSL 3.00
// (no SPIR-V: glslang makes SPIR-V only from ES 3.10 on), which refuses what ES 3.00 lacks
// (binding qualifiers, storage buffers, compute); then the WebGL 2.0 spec's own rules that
// glslang does not know (section 5 "Differences Between WebGL and OpenGL ES 3.0"): no
// identifier starting with "webgl_" or "_webgl_". (WebGL's 1024-character limit on identifiers
// is glslang's own: it refuses longer names.)
std::string checkWebgl2(const std::string& source, ShaderStage stage);
// glslang's HLSL front end reparses a compute (or fragment) shader (entry point "main"),
// generates SPIR-V for Vulkan 1.1 and runs spirv-val on it.
std::string checkHlsl(const std::string& source, bool fragment = false);
// No Metal compiler runs on Debian: the entry point (`kernel`, or `fragment` for a fragment
// module), the [[buffer(n)]] index that SPIRV-Cross assigned to every buffer and push-constant
// block, and the [[texture(n)]] and [[sampler(n)]] of every combined image sampler must appear
// in the source.
std::string checkMsl(const std::string& source, const SpvcModule& module);

}  // namespace mb
