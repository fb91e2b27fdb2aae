// write: `compile --depfile FILE` (docs/package.md "CMake"): every file a compile read, in
// Makefile syntax, so that a build system (CMake's add_custom_command DEPFILE) reruns the
// compile when any of them changes.
#pragma once
#include <set>
#include <string>
#include <vector>

#include "compile/build.hpp"
#include "library/shader_library.hpp"
#include "permute/permutation.hpp"

namespace mb {

// Adds every GLSL file an emitted permutation includes (from its #line directives), as an
// absolute path, to `out`: called per permutation as a streaming build hands them over.
void addGlslInputs(const ShaderLibrary& lib, const std::string& glsl, std::set<std::string>& out);

// Absolute, sorted, each once: `extra` (the scene file), every permutation's material source,
// its macro-form #includes and surface file, the shader library's manifest.json, slot.json
// files, glTF defaults and model JSONs, and `glslInputs` (addGlslInputs over the emitted permutations).
std::vector<std::string> compileInputs(const ShaderLibrary& lib, const std::vector<Permutation>& perms,
                                       const std::set<std::string>& glslInputs, const std::vector<std::string>& extra);

// "target: dep1 \\\n  dep2\n" with spaces, '#', ':' and '$' escaped the way Ninja (and GCC's -MD
// output, which Make reads) escape them. Throws DiagnosticError E-DEPFILE-PATH for a path no
// escape can carry (depfileRefusal).
std::string makeDepfile(const std::string& target, const std::vector<std::string>& deps);
// The depfile's target for package directory `out`: its manifest.json, absolute.
std::string depfileTarget(const std::string& out);
// Why the depfile cannot name `path` (a newline, tab or other control character, a trailing
// backslash or ':'), or empty when it can.
std::string depfileRefusal(const std::string& path);
// Throws DiagnosticError E-DEPFILE-PATH for the first of `target` and `deps` that the depfile
// cannot name: run before compiling, so that nothing is written for a depfile that would fail.
void checkDepfilePaths(const std::string& target, const std::vector<std::string>& deps);
// `path` with control characters as \xNN, for a one-line message.
std::string printablePath(const std::string& path);

}  // namespace mb
