// matbricks energy: white furnace, multiscatter compensation and reciprocity of every lobe,
// evaluated on the GPU and checked against the double references (compiler/energy/).
#include <iostream>

#include "cli/cli_common.hpp"
#include "cli/progress.hpp"
#include "energy/energy_checks.hpp"
#include "write/package_writer.hpp"

namespace mb::cli {
namespace {

struct EnergyArgs {
  bool json = false;
  bool markdown = false;
  std::string output;
  std::string grid = "fine";
  bool quiet = false;
};

int runEnergy(const EnergyArgs& a, const GlobalOptions& g) {
  if (!a.output.empty() && !a.markdown && !a.json) throw CLI::ValidationError("-o needs --markdown or --json");
  ShaderLibrary lib = loadLibrary(g);
  if (!a.output.empty()) checkFileOutput(a.output, "report", libraryInputs(lib));
  auto gpu = openDevice(g);
  energy::EnergyReport report;
  Progress progress("energy", 0, a.quiet,
                    (a.json || a.markdown) && a.output.empty());  // the checks add their units as they find them
  energy::runEnergyChecks(lib, *gpu, a.grid == "coarse" ? energy::EnergyGrid::coarse() : energy::EnergyGrid::fine(),
                          report, &progress);
  progress.finish();
  std::string command = "matbricks energy";
  if (a.grid != "fine") command += " --grid " + a.grid;
  std::string text;
  if (a.markdown) {
    text = energy::energyMarkdown(report, command + " --markdown -o docs/energy.md");
  } else if (a.json) {
    text = energy::energyJson(report).dump(2) + "\n";
  } else {
    text = energy::energyText(report);
  }
  if (a.output.empty()) {
    // -q keeps a report asked for on stdout (--json, --markdown) and drops the plain summary.
    if (!(a.quiet && !a.json && !a.markdown && report.failures().empty())) std::cout << text;
  } else {
    PackageWriter::writeFileAtomically(a.output, text);
  }
  for (const auto& f : report.failures()) std::cerr << "error: " << f << "\n";
  bool layer = reportLayerMessages(*gpu);
  return report.failures().empty() && !layer ? kExitOk : kExitCheckFailed;
}

}  // namespace

Command addEnergyCommand(CLI::App& app, GlobalOptions& g) {
  auto args = std::make_shared<EnergyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "energy", "White furnace, multiscatter compensation and reciprocity of every lobe (GPU vs reference)");
  cmd->add_flag("--json", args->json, "Everything, per grid cell, as JSON");
  cmd->add_flag("--markdown", args->markdown, "The report as Markdown (docs/energy.md)");
  cmd->add_option("-o,--output", args->output, "With --markdown or --json: write to this file (atomically)");
  cmd->add_option("--grid", args->grid, "fine (the published tables) or coarse (seconds; what the tests use)")
      ->check(CLI::IsMember({"fine", "coarse"}));
  cmd->add_flag("-q,--quiet", args->quiet,
                "No progress; the plain text summary only when a check fails (--json, --markdown still print)");
  return {cmd, [args, &g] { return runEnergy(*args, g); }};
}

}  // namespace mb::cli
