// Rewrites fp32 GLSL to half precision, token by token, for the fp16 precision axis:
//   float -> float16_t, vecN -> f16vecN, matN[xM] -> f16matN[xM], and every float literal gets
//   the `hf` suffix (glslang rejects the implicit float -> float16_t narrowing a bare literal
//   would need, GL_EXT_shader_explicit_arithmetic_types).
// Comments and preprocessor directives are copied verbatim, except #define bodies (a macro
// such as MB_PI expands into half expressions). Identifiers are matched whole, so
// floatBitsToUint or my_vec3 stay as they are. Line structure is kept, so #line directives
// still point at the brick's own lines.
#pragma once
#include <string>

namespace mb {

std::string rewriteToFp16(const std::string& glsl);

}  // namespace mb
