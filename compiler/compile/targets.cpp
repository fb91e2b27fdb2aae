// INTERIM (replaced by the SPIRV-Cross implementation).
#include "compile/targets.hpp"

#include "core/diagnostics.hpp"

namespace mb {

const std::vector<std::string>& allTargets() {
  static const std::vector<std::string> t{"spirv", "glsl450", "essl310", "hlsl", "msl"};
  return t;
}

std::string targetExtension(const std::string& target) {
  if (target == "spirv") return ".spv";
  if (target == "glsl450") return ".comp";
  if (target == "essl310") return ".es.comp";
  if (target == "hlsl") return ".hlsl";
  return ".metal";
}

nlohmann::json reflectSpirv(const std::vector<uint32_t>&) { return nlohmann::json::object(); }

std::string crossCompile(const std::vector<uint32_t>&, const std::string& target, const std::string& displayName) {
  throw DiagnosticError({{Severity::Error, "E-TARGET-FAILED", {displayName, 0, 0}, "target " + target + " not built yet"}});
}

std::string spirvCrossVersion() { return "unknown"; }

}  // namespace mb
