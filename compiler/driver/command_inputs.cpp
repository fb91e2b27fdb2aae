#include "driver/command_inputs.hpp"

#include <set>

#include "load/gltf_external_files.hpp"
#include "load/project_files.hpp"

namespace mb {

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

std::vector<MaterialDesc> loadMaterialFiles(const std::vector<std::string>& paths, const ShaderLibrary& lib,
                                            std::vector<Diagnostic>& warnings) {
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
  for (const auto& m : out) warnings.insert(warnings.end(), m.warnings.begin(), m.warnings.end());
  return out;
}

}  // namespace mb
