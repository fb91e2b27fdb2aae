// matbricks: the command-line front end. Each subcommand lives in its own cmd_*.cpp.
#include <iostream>

#include "cli/cli_common.hpp"
#include "compile/glsl_compiler.hpp"
#include "compile/targets.hpp"
#include "glrun/gl_compute.hpp"
#include "webgl/webgl_draw.hpp"

using namespace mb;
using namespace mb::cli;

int main(int argc, char** argv) {
  CLI::App app{"matbricks " MB_VERSION ": PBR brick library, material compiler and validator"};
  app.require_subcommand(1);
  app.set_version_flag(
      "--version", std::string("matbricks " MB_VERSION " (") + toolchainVersion() + "; " + spirvCrossVersion() + ")");
  GlobalOptions g;
  app.add_option(
      "--shaderlib", g.shaderlib,
      "Brick library root (default: $MATBRICKS_SHADERLIB, else the installed share/matbricks/shaderlib beside the program, else the source tree's)");
  app.add_option("--device", g.device, "Vulkan device: case-insensitive substring of its name (default: lavapipe)");
  app.add_flag("--vk-validation", g.vulkanValidation, "Enable the Khronos validation layer; any message fails the run");
  app.add_option("--diagnostics-format", g.diagnosticsFormat, "How errors are printed")
      ->check(CLI::IsMember({"text", "json"}));

  std::vector<Command> commands{addCompileCommand(app, g), addValidateCommand(app, g), addBricksCommand(app, g),
                                addEvalCommand(app, g)};
  commands.push_back(addBenchCommand(app, g));
  commands.push_back(addLutCommand(app, g));
  commands.push_back(addLtcCommand(app, g));
  commands.push_back(addEnergyCommand(app, g));
  commands.push_back(addStressCommand(app, g));
  commands.push_back(addVerifyCommand(app, g));
  commands.push_back(addMergeCommand(app, g));
  commands.push_back(addPreviewCommand(app, g));
  commands.push_back(addReportCommand(app, g));

  // A list option takes one value per use, "a,b" or "--x a --x b", never the words after it:
  // CLI11's default would read `compile --targets msl m.json` as the targets msl and m.json.
  for (const Command& c : commands)
    for (CLI::Option* o : c.app->get_options())
      if (!o->get_positional() && o->get_items_expected_max() > 1) o->allow_extra_args(false);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }
  try {
    for (auto& c : commands)
      if (c.app->parsed()) return c.run();
  } catch (const DiagnosticError& e) {
    printDiagnostics(e.diagnostics(), g);
    // E-INTERNAL is matbricks' own inconsistency, not the input's (exit 5, docs/cli.md).
    for (const auto& d : e.diagnostics())
      if (d.code == "E-INTERNAL") return kExitInternalError;
    return kExitInputError;
  } catch (const CLI::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitUsage;
  } catch (const harness::HarnessError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitDeviceError;
  } catch (const gl::GlError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitDeviceError;
  } catch (const webgl::WebglError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitDeviceError;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return kExitInternalError;
  }
  return kExitUsage;
}
