// The fragment stage's reference vertex shader (shaderlib/common/engine_vertex.vert,
// docs/fragment-stage.md) in a target's language. The webgl2 package ships it: a WebGL 2.0
// program links a vertex and a fragment shader of the same language, and an engine that runs
// the package's ESSL 3.00 may have no GLSL toolchain of its own (docs/targets.md "WebGL 2.0").
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/target.hpp"

namespace mb {

class ShaderLibrary;

// engine_vertex.vert compiled by glslang (Vulkan GLSL, a vertex shader).
std::vector<uint32_t> referenceVertexSpirv(const ShaderLibrary& lib);

// Its text in `target` (crossCompile, checked as the target's vertex shader).
std::string referenceVertexShader(const ShaderLibrary& lib, Target target);

// The package path of the webgl2 vertex shader, and what a WebGL 2.0 program binds of it by
// name: {"file", "attributes": [{"name","location","type"}], "block": {"name","layout","size",
// "members"}} (its push-constant block, a std140 uniform block in GL).
extern const char* const kWebgl2VertexPath;
nlohmann::json webgl2VertexJson(const ShaderLibrary& lib);

}  // namespace mb
