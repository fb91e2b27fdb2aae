// matbricks bricks: the catalogue, with each brick's signature and probe inputs.
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/cli_common.hpp"
#include "common/reference.hpp"
#include "emit/emitter.hpp"

namespace mb::cli {
namespace {

struct BricksArgs {
  bool json = false;
  std::string slot;
};

std::string signatureOf(const Brick& b, const Slot& s) {
  std::string sig = toString(s.returns) + " " + b.function + "(";
  for (size_t i = 0; i < s.params.size(); ++i)
    sig += (i ? ", " : "") + toString(s.params[i].type) + " " + s.params[i].name;
  return sig + ")";
}

nlohmann::json brickJson(const ShaderLibrary& lib, const Brick& b) {
  const Slot& s = *lib.findSlot(b.slot);
  nlohmann::json domain = nlohmann::json::object();
  for (const auto& [k, r] : b.domain) domain[k] = {r.lo, r.hi};
  return {{"id", b.id},
          {"slot", b.slot},
          {"name", b.name},
          {"function", b.function},
          {"signature", signatureOf(b, s)},
          {"file", ShaderLibrary::displayPath(b.file)},
          {"citation", b.citation},
          {"inputs", emitBrickProbe(lib, b).layout.columns()},
          {"domain", domain},
          {"geometry", {{"NoV", {b.geometry.NoV.lo, b.geometry.NoV.hi}},
                        {"NoL", {b.geometry.NoL.lo, b.geometry.NoL.hi}}}},
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
    throw DiagnosticError({{Severity::Error, "E-UNKNOWN-SLOT", {"<command line>", 0, 0},
                            "unknown slot '" + a.slot + "'", didYouMean(a.slot, names)}});
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
      std::printf("  %-32s %s\n", b.id.c_str(), signatureOf(b, s).c_str());
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
  return {cmd, [args, &g] { return runBricks(*args, g); }};
}

}  // namespace mb::cli
