// The identifiers a GLSL source declares at global scope, read from glslang's AST: what a
// user's name must not repeat once it is pasted into that source (load/glsl_names.hpp).
#pragma once
#include <map>
#include <optional>
#include <string>

#include "compile/glsl_compiler.hpp"

namespace mb {

// name -> what it is and where it is declared ("a function of common/geometry.glsl"), for
// every function, global variable or constant (members of an anonymous interface block
// included), struct type and interface block name of `source`, after preprocessing (so only
// what the #if branches taken declare). nullopt when glslang does not parse the source.
// Locals and parameters of functions are not global and are not listed.
std::optional<std::map<std::string, std::string>> glslGlobalDeclarations(const std::string& source,
                                                                         ShaderStage stage = ShaderStage::Compute);

}  // namespace mb
