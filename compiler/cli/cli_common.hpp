// Pieces every subcommand shares: exit codes, options, loading inputs, printing errors.
#pragma once
#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

#include "cli/input_forms.hpp"
#include "core/diagnostics.hpp"
#include "driver/command_inputs.hpp"   // libraryInputs, addMaterialInputs, checkDirectoryOutput, ...
#include "driver/validation_plan.hpp"  // permutationsToValidate
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
// Loads every material, collecting the diagnostics of all files before failing
// (driver/command_inputs.hpp loadMaterialFiles). Warnings (an unsupported glTF extension, ...)
// are printed in the --diagnostics-format.
std::vector<MaterialDesc> loadMaterials(const std::vector<std::string>& paths, const ShaderLibrary& lib,
                                        const GlobalOptions& g);
// Throws DiagnosticError `code` ("unknown <what> 'x'" with a did-you-mean) for every name of
// `names` not in `known` (bench's and report's --slot, bench's --brick).
void checkKnownNames(const std::vector<std::string>& names, const std::vector<std::string>& known, const char* code,
                     const char* what);

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
