// matbricks bricks: the catalogue, with each brick's signature and probe inputs.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/cli_common.hpp"
#include "common/reference.hpp"
#include "core/input_file.hpp"
#include "emit/emitter.hpp"
#include "library/signature.hpp"
#include "write/package_writer.hpp"
#include "validate/brick_catalogue.hpp"

namespace mb::cli {
namespace {

struct BricksArgs {
  bool json = false;
  bool markdown = false;
  std::string output;
  std::string slot;
  bool noGpu = false;
};

nlohmann::json brickJson(const ShaderLibrary& lib, const Brick& b) {
  const Slot& s = *lib.findSlot(b.slot);
  nlohmann::json domain = nlohmann::json::object();
  for (const auto& [k, r] : b.domain) domain[k] = {r.lo, r.hi};
  return {
      {"id", b.id},
      {"slot", b.slot},
      {"name", b.name},
      {"function", b.function},
      {"signature", brickSignature(b, s)},
      {"file", ShaderLibrary::displayPath(b.file)},
      {"citation", b.citation},
      {"inputs", emitBrickProbe(lib, b).layout.columns()},
      {"domain", domain},
      {"geometry", {{"NoV", {b.geometry.NoV.lo, b.geometry.NoV.hi}}, {"NoL", {b.geometry.NoL.lo, b.geometry.NoL.hi}}}},
      {"tolerance", {{"abs", b.tolerance.abs}, {"rel", b.tolerance.rel}, {"reason", b.tolerance.reason}}},
      {"has_reference", ref::Registry::references().find(b.id) != nullptr},
      {"has_ground_truth", ref::Registry::groundTruths().find(b.id) != nullptr},
      {"notes", b.notes}};
}

int runBricks(const BricksArgs& a, const GlobalOptions& g) {
  ShaderLibrary lib = loadLibrary(g);
  if (!a.slot.empty() && !lib.findSlot(a.slot)) {
    std::vector<std::string> names;
    for (const auto& s : lib.slots()) names.push_back(s.name);
    throw DiagnosticError({{Severity::Error,
                            "E-UNKNOWN-SLOT",
                            {"<command line>", 0, 0},
                            "unknown slot '" + a.slot + "'",
                            didYouMean(a.slot, names)}});
  }
  if (a.noGpu && (!a.markdown || a.output.empty()))
    throw CLI::ValidationError("--no-gpu needs --markdown -o FILE: the figures are carried over from FILE");
  if (a.markdown) {
    if (!a.output.empty()) checkFileOutput(a.output, "catalogue", libraryInputs(lib));
    if (a.noGpu) {
      // The figures FILE already prints, for the bricks it lists (none when it does not exist).
      std::string previous;
      if (std::filesystem::exists(a.output)) previous = readInputFileOrThrow(a.output, input_kind::kMarkdown);
      PackageWriter::writeFileAtomically(a.output, brickCatalogueMarkdown(lib, carriedCatalogueFigures(lib, previous)));
      return kExitOk;
    }
    auto gpu = openDevice(g);
    std::string md = brickCatalogueMarkdown(lib, *gpu);
    if (a.output.empty()) {
      std::cout << md;
    } else {
      PackageWriter::writeFileAtomically(a.output, md);
    }
    return reportLayerMessages(*gpu) ? kExitCheckFailed : kExitOk;
  }
  if (a.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& b : lib.bricks())
      if (a.slot.empty() || b.slot == a.slot) out.push_back(brickJson(lib, b));
    std::cout << out.dump(2) << "\n";
    return kExitOk;
  }
  for (const auto& s : lib.slots()) {
    if (!a.slot.empty() && s.name != a.slot) continue;
    std::printf("[%s] %s\n", s.name.c_str(), s.description.c_str());
    for (const auto& b : lib.bricks()) {
      if (b.slot != s.name) continue;
      std::printf("  %-32s %s\n", b.id.c_str(), brickSignature(b, s).c_str());
      std::printf("  %-32s inputs: ", "");
      auto cols = emitBrickProbe(lib, b).layout.columns();
      for (size_t i = 0; i < cols.size(); ++i) std::printf("%s%s", i ? "," : "", cols[i].c_str());
      std::printf("\n  %-32s source: %s\n", "", b.citation.c_str());
    }
  }
  return kExitOk;
}

}  // namespace

Command addBricksCommand(CLI::App& app, GlobalOptions& g) {
  auto args = std::make_shared<BricksArgs>();
  CLI::App* cmd = app.add_subcommand("bricks", "List the brick catalogue");
  cmd->add_flag("--json", args->json, "Machine-readable catalogue");
  cmd->add_option("--slot", args->slot, "Only this slot");
  cmd->add_flag("--markdown", args->markdown,
                "The catalogue as Markdown with errors measured on the GPU (docs/bricks.md)");
  cmd->add_option("-o,--output", args->output, "With --markdown: write to this file (atomically) instead of stdout");
  cmd->add_flag("--no-gpu", args->noGpu,
                "With --markdown -o FILE: no device; the library's parts regenerated, the measured figures carried "
                "over from FILE for the bricks it lists (a new brick shows 'not measured')");
  return {cmd, [args, &g] { return runBricks(*args, g); }};
}

}  // namespace mb::cli
