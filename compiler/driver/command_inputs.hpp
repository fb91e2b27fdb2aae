// What a command reads, which its outputs must stay clear of (docs/cli.md "Outputs"), and the
// checks of an output against it: the compile run (driver/compile_run.hpp) and every
// subcommand that writes a file or a directory use them.
#pragma once
#include <string>
#include <vector>

#include "library/shader_library.hpp"
#include "load/material_desc.hpp"
#include "write/output_paths.hpp"

namespace mb {

// The shader library.
std::vector<ProtectedPath> libraryInputs(const ShaderLibrary& lib);
// Each material's description, #includes, surface file and, for glTF, the buffers and images
// it names; `sceneFile`, when given, is protected too, with the glTF buffers and images it
// names (each glTF file's URIs are read once, whether it is the scene, a material's file, or
// both).
void addMaterialInputs(std::vector<ProtectedPath>& inputs, const std::vector<const MaterialDesc*>& materials,
                       const std::string& sceneFile = "");
void addMaterialInputs(std::vector<ProtectedPath>& inputs, const std::vector<MaterialDesc>& materials);
// Before any work: a directory output must be new, empty or one matbricks wrote, and no
// output may be, contain or lie inside an input. Throws DiagnosticError (exit 3).
void checkDirectoryOutput(const std::string& dir, const std::vector<ProtectedPath>& inputs);
void checkFileOutput(const std::string& file, const std::string& what, const std::vector<ProtectedPath>& inputs);

// Loads every material, collecting the diagnostics of all files before failing (one
// DiagnosticError); their warnings (an unsupported glTF extension, ...) are appended to
// `warnings`.
std::vector<MaterialDesc> loadMaterialFiles(const std::vector<std::string>& paths, const ShaderLibrary& lib,
                                            std::vector<Diagnostic>& warnings);

}  // namespace mb
