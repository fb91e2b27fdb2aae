// matbricks ltc: fit the linearly transformed cosines of a cosine-weighted lobe (Heitz et al.
// 2016), the GGX specular or the Charlie sheen, and write the table the LTC area-light bricks
// read (docs/models/lights.md "LTC tables").
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "cli/cli_common.hpp"
#include "ltc/ltc_table.hpp"
#include "write/package_writer.hpp"

namespace mb::cli {
namespace {

struct LtcArgs {
  std::string lobe = "ggx";
  uint32_t size = 64;
  uint32_t samples = 32;
  uint32_t threads = 0;
  std::string output;
  bool quiet = false;
};

int runLtc(const LtcArgs& a, const GlobalOptions& g) {
  checkFileOutput(a.output, "LTC table", libraryInputs(loadLibrary(g)));
  ltc::FitSettings settings;
  settings.lobe = a.lobe == "charlie" ? ltc::LobeKind::Charlie : ltc::LobeKind::Ggx;
  settings.samples = a.samples;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<ltc::LtcEntry> fitted = ltc::fitTable(a.size, settings, a.threads);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const ltc::Table table = ltc::makeTable(a.size, settings, fitted);
  const std::string command = "matbricks ltc --lobe " + a.lobe + " --size " + std::to_string(a.size) + " --samples " +
                              std::to_string(a.samples) + " -o " + a.output;
  PackageWriter::writeFileAtomically(a.output, ltc::encodeTable(table, command));
  if (!a.quiet) {
    uint32_t iterations = 0;
    for (const auto& e : fitted) iterations = std::max(iterations, e.iterations);
    std::printf(
        "LTC table of the %s lobe, %ux%u (%u^2 samples per error estimate), fitted in %.1f s; at most %u "
        "iterations\n",
        a.lobe.c_str(), a.size, a.size, a.samples, seconds, iterations);
    std::printf("wrote %s\n", a.output.c_str());
  }
  return kExitOk;
}

}  // namespace

Command addLtcCommand(CLI::App& app, GlobalOptions& g) {
  auto args = std::make_shared<LtcArgs>();
  CLI::App* cmd = app.add_subcommand("ltc", "Fit the LTC table of the GGX or the sheen lobe for the area-light bricks");
  cmd->add_option("--lobe", args->lobe, "ggx (the specular lobe, default) or charlie (the sheen lobe)")
      ->check(CLI::IsMember({"ggx", "charlie"}));
  cmd->add_option("--size", args->size, "Entries per side (default 64)")->check(CLI::Range(2u, 1024u));
  cmd->add_option("--samples", args->samples, "Stratified samples per side of each error estimate (default 32)")
      ->check(CLI::Range(4u, 1024u));
  cmd->add_option("-j,--jobs", args->threads, "Threads (default: all cores); the table does not depend on it");
  cmd->add_option("-o,--output", args->output, "Output file, written atomically")->required();
  cmd->add_flag("-q,--quiet", args->quiet, "No summary");
  return {cmd, [args, &g] { return runLtc(*args, g); }};
}

}  // namespace mb::cli
