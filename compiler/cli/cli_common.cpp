#include "cli/cli_common.hpp"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <set>

#include "load/gltf_external_files.hpp"
#include "permute/axes.hpp"
#include "load/project_files.hpp"

namespace mb::cli {

ShaderLibrary loadLibrary(const GlobalOptions& g) {
  return ShaderLibrary::load(g.shaderlib.empty() ? ShaderLibrary::defaultRoot() : std::filesystem::path(g.shaderlib));
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

std::vector<ProtectedPath> libraryInputs(const ShaderLibrary& lib) { return {{lib.root(), "shader library"}}; }

void addMaterialInputs(std::vector<ProtectedPath>& inputs, const std::vector<MaterialDesc>& materials) {
  std::vector<const MaterialDesc*> all;
  for (const auto& m : materials) all.push_back(&m);
  addMaterialInputs(inputs, all);
}

void addMaterialInputs(std::vector<ProtectedPath>& inputs, const std::vector<const MaterialDesc*>& materials,
                       const std::string& sceneFile) {
  std::set<std::string> gltfFiles;  // a glTF file holds many materials: read its URIs once
  auto add = [&](const std::string& file, const char* what) {
    inputs.push_back({file, what});
    const std::string ext = lowerExtension(file);
    if ((ext == ".gltf" || ext == ".glb") && gltfFiles.insert(file).second)
      for (const auto& f : gltfExternalFiles(file)) inputs.push_back({f, "glTF buffer or image"});
  };
  if (!sceneFile.empty()) add(sceneFile, "scene");
  for (const MaterialDesc* m : materials) {
    add(m->sourceFile, "material");
    for (const auto& inc : m->includedFiles) inputs.push_back({inc, "#included file"});
    if (m->surface.present()) inputs.push_back({m->surface.where.file, "surface file"});
  }
}

void checkDirectoryOutput(const std::string& dir, const std::vector<ProtectedPath>& inputs) {
  checkOutputDirectory(dir);
  refuseOverlap(dir, "output directory", inputs);
}

void checkFileOutput(const std::string& file, const std::string& what, const std::vector<ProtectedPath>& inputs) {
  refuseOverlap(resolvedOutputFile(file), what, inputs);
  checkOutputFile(file);
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

std::vector<Permutation> permutationsToValidate(const MaterialDesc& m, const ShaderLibrary& lib,
                                                const std::vector<std::string>& lights,
                                                const std::vector<EnvironmentMode>& environments, Precision precision,
                                                std::vector<std::string>& notes) {
  std::vector<Permutation> out;
  for (auto perm : validationPermutationsFor(m, lib)) {
    if (!environments.empty() &&
        std::find(environments.begin(), environments.end(), perm.environment) == environments.end())
      continue;
    if (!lights.empty()) perm.lights = canonicalLights(lights);
    perm.precision = precision;
    if (environments.empty())
      if (auto broken = brokenBrickRule(*lib.findModel(m.model), perm)) {
        notes.push_back("skipping environment '" + environmentModeName(perm.environment) + "': " + broken->message);
        continue;
      }
    out.push_back(perm);
  }
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
