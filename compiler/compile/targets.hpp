// compile: the output languages of a permutation (DESIGN.md vocabulary "target") and their
// checks. SPIR-V comes from glslang + spirv-opt; the others from SPIRV-Cross's C API
// (libspirv-cross-c-shared). Every output is checked before it is kept (docs/targets.md):
//   spirv    spirv-val (SPIRV-Tools, Vulkan 1.1 rules)
//   glsl450  glslang reparses it as a GLSL 450 compute shader and generates SPIR-V
//   essl310  glslang reparses it as ESSL 3.10 (#version 310 es) and generates SPIR-V
//   hlsl     glslang's HLSL front end reparses it (shader model 6.0 source) and generates SPIR-V
//   webgl2   (fragment and vertex shaders only) glslang parses and links it as ESSL 3.00, plus
//            the WebGL 2.0 identifier rules (target_checks.hpp checkWebgl2)
//   msl      no Metal compiler runs on Debian: SPIRV-Cross must succeed, and the kernel's entry
//            point and the [[buffer(n)]] index of every buffer it uses must appear in the source
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/target.hpp"  // Target, its TargetInfo row, allTargets() in package order

namespace mb {

// File extension of a target's output in the package: ".spv", ".comp", ".es.comp", ".hlsl", ".metal".
std::string targetExtension(Target target);
// The same for a fragment shader: ".spv", ".frag", ".es.frag", ".hlsl", ".metal".
std::string fragmentExtension(Target target);

// SPIRV-Cross's view of a module, as the package manifest stores it (docs/package.md):
//   {"entry_point": "main", "workgroup_size": [64,1,1],
//    "storage_buffers": [{"name","set","binding","readonly","writeonly","size","members":[...]}],
//    "uniform_buffers": [{"name","set","binding","size","members":[{"name","type","offset","size"}]}],
//    "push_constants": [{"name","size","members":[...]}]}
// member "type" is the GLSL type name ("float", "vec3", "uint", "float[]"). A module that is
// not a compute shader also has "stage" ("fragment"), "stage_inputs" and "stage_outputs"
// ([{"name","location","type"}] by location) and "sampled_images"
// ([{"name","set","binding","type"}], type "sampler2D" / "samplerCube").
nlohmann::json reflectSpirv(const std::vector<uint32_t>& spirv);

// Cross-compiles one module to `target` (not Target::Spirv) and checks the result as above.
// Throws DiagnosticError (E-TARGET-FAILED naming `displayName`, the target and the checker's
// first message) when SPIRV-Cross or the check fails.
std::string crossCompile(const std::vector<uint32_t>& spirv, Target target, const std::string& displayName);

// The options `target` is cross-compiled with (version, dialect, bindings), as one line, so
// that the cache key changes when they do.
std::string targetOptions(Target target);

// Versions of SPIRV-Cross (for the cache key and `--version`).
std::string spirvCrossVersion();

}  // namespace mb
