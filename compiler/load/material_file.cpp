// loadMaterialFile: one entry point for every description form, picked by extension, so each
// subcommand accepts them all (docs/cli.md).
#include "load/material_desc.hpp"
#include "load/project_files.hpp"

#if __has_include("load/gltf_import.hpp")
#include "load/gltf_import.hpp"
#define MB_HAVE_GLTF_IMPORT 1
#endif

namespace mb {

std::vector<MaterialDesc> loadMaterialFile(const std::string& path, const ShaderLibrary& lib) {
  const std::string ext = lowerExtension(path);
  if (ext == ".json") return {loadMaterialJson(path, lib)};
  if (ext == ".mat") return {loadMaterialMacro(path, lib)};
  if (ext == ".gltf" || ext == ".glb") {
#ifdef MB_HAVE_GLTF_IMPORT
    return importGltfMaterials(path, lib);
#else
    throw DiagnosticError({{Severity::Error, "E-UNSUPPORTED-FORMAT", SourceLocation(path, 0, 0),
                            "glTF import is not built in yet: expected a .json or .mat material"}});
#endif
  }
  throw DiagnosticError({{Severity::Error, "E-UNSUPPORTED-FORMAT", SourceLocation(path, 0, 0),
                          "unsupported material file extension '" + ext +
                              "': expected .json (material JSON), .mat (macro form), .gltf or .glb (glTF 2.0)"}});
}

}  // namespace mb
