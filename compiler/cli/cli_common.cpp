#include "cli/cli_common.hpp"

#include <cstdlib>
#include <iostream>

namespace mb::cli {

ShaderLibrary loadLibrary(const GlobalOptions& g) {
  return ShaderLibrary::load(g.shaderlib.empty() ? ShaderLibrary::defaultRoot()
                                                 : std::filesystem::path(g.shaderlib));
}

std::vector<MaterialDesc> loadMaterials(const std::vector<std::string>& paths, const ShaderLibrary& lib,
                                        const GlobalOptions& g) {
  std::vector<MaterialDesc> out;
  std::vector<Diagnostic> errors;
  for (const auto& p : paths) {
    try {
      for (auto& m : loadMaterialFile(p, lib)) out.push_back(std::move(m));
    } catch (const DiagnosticError& e) {
      errors.insert(errors.end(), e.diagnostics().begin(), e.diagnostics().end());
    }
  }
  if (!errors.empty()) throw DiagnosticError(errors);
  // Warnings (an unsupported glTF extension, alpha not shaded, ...) do not stop the run.
  std::vector<Diagnostic> warnings;
  for (const auto& m : out) warnings.insert(warnings.end(), m.warnings.begin(), m.warnings.end());
  if (!warnings.empty()) printDiagnostics(warnings, g);
  return out;
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
