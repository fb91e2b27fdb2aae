// write: include/<key>.hlsl and include/<key>.metal (docs/package.md "HLSL and MSL
// includes"). The body comes from the build (compile/engine_includes.hpp), made through
// SPIR-V from the same GLSL as include/<key>.glsl; this file adds what an engine programmer
// reads first: which permutation it is, the hooks to define and the functions to call, with
// the exact signatures of the language.
#include <sstream>

#include "compile/engine_includes.hpp"
#include "core/target.hpp"
#include "write/package_parts.hpp"

namespace mb {

std::string crossIncludePath(const std::string& key, const std::string& target) {
  return "include/" + key + targetInfo(target).includeExtension;
}

std::string crossInclude(const PackagedPermutation& p, const std::string& target, const std::string& body) {
  const bool msl = targetInfo(target).language == TargetLanguage::Msl;
  std::ostringstream out;
  out << includeOrigin(p, msl ? "MSL" : "HLSL")
      << "// Made by SPIRV-Cross from the SPIR-V of the GLSL include's code (no inlining), so both\n"
      << "// compute the same values. Include it once per shader.\n";
  const auto hooks = hookPrototypes(body);
  if (!hooks.empty()) {
    out << "// The engine defines the environment hooks, with exactly these signatures:\n";
    for (const auto& h : hooks) out << "//   " << h.text << "\n";
  }
  out << "// Entry points (docs/models.md \"GLSL contract\"):\n";
  for (const auto& f : contractFunctions(body)) out << "//   " << f.text << "\n";
  const std::string guard = includeGuard(p.built->shader.key, msl ? "_METAL" : "_HLSL");
  out << "#ifndef " << guard << "\n#define " << guard << "\n\n" << body << "#endif  // " << guard << "\n";
  return out.str();
}

}  // namespace mb
