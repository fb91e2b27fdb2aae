#include "cli/cli_common.hpp"

#include <algorithm>
#include <cstdlib>
#include <iostream>

namespace mb::cli {

ShaderLibrary loadLibrary(const GlobalOptions& g) {
  return ShaderLibrary::load(g.shaderlib.empty() ? ShaderLibrary::defaultRoot() : std::filesystem::path(g.shaderlib));
}

std::vector<MaterialDesc> loadMaterials(const std::vector<std::string>& paths, const ShaderLibrary& lib,
                                        const GlobalOptions& g) {
  std::vector<Diagnostic> warnings;
  std::vector<MaterialDesc> out = loadMaterialFiles(paths, lib, warnings);
  if (!warnings.empty()) printDiagnostics(warnings, g);
  return out;
}

void checkKnownNames(const std::vector<std::string>& names, const std::vector<std::string>& known, const char* code,
                     const char* what) {
  std::vector<Diagnostic> errors;
  for (const auto& n : names)
    if (std::find(known.begin(), known.end(), n) == known.end())
      errors.push_back({Severity::Error,
                        code,
                        {"<command line>", 0, 0},
                        std::string("unknown ") + what + " '" + n + "'",
                        didYouMean(n, known)});
  if (!errors.empty()) throw DiagnosticError(errors);
}

std::unique_ptr<harness::VulkanHarness> openDevice(const GlobalOptions& g) {
  harness::DeviceOptions o;
  o.device = g.device;
  const char* env = std::getenv("MATBRICKS_VALIDATION");
  o.validation = g.vulkanValidation || (env && std::string(env) == "1");
  return std::make_unique<harness::VulkanHarness>(o);
}

bool reportLayerMessages(const harness::VulkanHarness& gpu) {
  auto msgs = gpu.validationMessages();
  for (const auto& m : msgs) std::cerr << "vulkan validation: " << m << "\n";
  return !msgs.empty();
}

void printDiagnostics(const std::vector<Diagnostic>& diags, const GlobalOptions& g) {
  if (g.diagnosticsFormat == "json") {
    std::cerr << diagnosticsToJson(diags) << "\n";
    return;
  }
  for (const auto& d : diags) std::cerr << formatDiagnostic(d) << "\n";
}

}  // namespace mb::cli
