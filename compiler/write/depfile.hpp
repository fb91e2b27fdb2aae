// write: `compile --depfile FILE` (docs/package.md "CMake"): every file a compile read, in
// Makefile syntax, so that a build system (CMake's add_custom_command DEPFILE) reruns the
// compile when any of them changes.
#pragma once
#include <string>
#include <vector>

#include "compile/build.hpp"
#include "library/shader_library.hpp"
#include "permute/permutation.hpp"

namespace mb {

// Absolute, sorted, each once: `extra` (the scene file), every permutation's material source,
// its macro-form #includes and surface file, the shader library's manifest.json, slot.json files and model JSONs, and
// every GLSL file the emitted permutations include (from their #line directives).
std::vector<std::string> compileInputs(const ShaderLibrary& lib, const std::vector<Permutation>& perms,
                                       const std::vector<BuiltPermutation>& built,
                                       const std::vector<std::string>& extra);

// "target: dep1 \\\n  dep2\n" with spaces, '#' and '$' escaped the way Make and Ninja read them.
std::string makeDepfile(const std::string& target, const std::vector<std::string>& deps);

}  // namespace mb
