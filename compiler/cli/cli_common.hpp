// Pieces every subcommand shares: exit codes, options, loading inputs, printing errors.
#pragma once
#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

#include "cli/input_forms.hpp"
#include "core/diagnostics.hpp"
#include "harness/vulkan_harness.hpp"
#include "library/shader_library.hpp"
#include "load/material_desc.hpp"
#include "permute/permutation.hpp"
#include "write/output_paths.hpp"

namespace mb::cli {

// Documented in docs/cli.md.
enum ExitCode : int {
  kExitOk = 0,
  kExitCheckFailed = 1,   // validation/eval found errors beyond tolerance (or layer messages)
  kExitUsage = 2,         // bad command line
  kExitInputError = 3,    // bad input file: JSON, unknown brick, GLSL error, missing file
  kExitDeviceError = 4,   // no Vulkan device, or a Vulkan failure
  kExitInternalError = 5  // a bug in matbricks
};

struct GlobalOptions {
  std::string shaderlib;                   // --shaderlib; empty = default root
  std::string device;                      // --device substring
  bool vulkanValidation = false;           // --vk-validation or MATBRICKS_VALIDATION=1
  std::string diagnosticsFormat = "text";  // --diagnostics-format text|json
};

ShaderLibrary loadLibrary(const GlobalOptions& g);
// Loads every material, collecting the diagnostics of all files before failing.
// Warnings (an unsupported glTF extension, ...) are printed in the --diagnostics-format.
std::vector<MaterialDesc> loadMaterials(const std::vector<std::string>& paths, const ShaderLibrary& lib,
                                        const GlobalOptions& g);
// What a command reads, which its outputs must stay clear of (docs/cli.md "Outputs"): the
// shader library, and each material's description, #includes, surface file and, for glTF,
// the buffers and images it names.
std::vector<ProtectedPath> libraryInputs(const ShaderLibrary& lib);
// `sceneFile`, when given, is protected too, with the glTF buffers and images it names (each
// glTF file's URIs are read once, whether it is the scene, a material's file, or both).
void addMaterialInputs(std::vector<ProtectedPath>& inputs, const std::vector<const MaterialDesc*>& materials,
                       const std::string& sceneFile = "");
void addMaterialInputs(std::vector<ProtectedPath>& inputs, const std::vector<MaterialDesc>& materials);
// Before any work: a directory output must be new, empty or one matbricks wrote, and no
// output may be, contain or lie inside an input. Throws DiagnosticError (exit 3).
void checkDirectoryOutput(const std::string& dir, const std::vector<ProtectedPath>& inputs);
void checkFileOutput(const std::string& file, const std::string& what, const std::vector<ProtectedPath>& inputs);

// Throws DiagnosticError `code` ("unknown <what> 'x'" with a did-you-mean) for every name of
// `names` not in `known` (bench's and report's --slot, bench's --brick).
void checkKnownNames(const std::vector<std::string>& names, const std::vector<std::string>& known, const char* code,
                     const char* what);

// The permutations validated for one material (validate, report): the model's light types
// together, once per environment mode, both narrowed by `lights` / `environments` (empty: all),
// at `precision`. A mode in which the material's bricks break one of the model's brick rules is
// skipped with a note when the user did not ask for it (the material may be meant for other
// modes); asked for, it is an error when the probe is built.
std::vector<Permutation> permutationsToValidate(const MaterialDesc& m, const ShaderLibrary& lib,
                                                const std::vector<std::string>& lights,
                                                const std::vector<EnvironmentMode>& environments, Precision precision,
                                                std::vector<std::string>& notes);

std::unique_ptr<harness::VulkanHarness> openDevice(const GlobalOptions& g);
// Prints validation-layer messages to stderr; returns true if there were any.
bool reportLayerMessages(const harness::VulkanHarness& gpu);

void printDiagnostics(const std::vector<Diagnostic>& diags, const GlobalOptions& g);

// Subcommands: each registers itself on `app` and returns the code to exit with.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};
Command addCompileCommand(CLI::App& app, GlobalOptions& g);
Command addValidateCommand(CLI::App& app, GlobalOptions& g);
Command addBricksCommand(CLI::App& app, GlobalOptions& g);
Command addEvalCommand(CLI::App& app, GlobalOptions& g);
Command addStressCommand(CLI::App& app, GlobalOptions& g);
Command addBenchCommand(CLI::App& app, GlobalOptions& g);
Command addLutCommand(CLI::App& app, GlobalOptions& g);
Command addLtcCommand(CLI::App& app, GlobalOptions& g);
Command addEnergyCommand(CLI::App& app, GlobalOptions& g);
Command addVerifyCommand(CLI::App& app, GlobalOptions& g);
Command addMergeCommand(CLI::App& app, GlobalOptions& g);
Command addPreviewCommand(CLI::App& app, GlobalOptions& g);
Command addReportCommand(CLI::App& app, GlobalOptions& g);

}  // namespace mb::cli
