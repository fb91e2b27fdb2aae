// matbricks bench: run time against error per slot, per example material permutation and
// for the DFG LUT choices (compiler/bench_engine/). Results as JSON, CSV, SVG Pareto charts and the
// Markdown tables of docs/accuracy.md.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "bench_engine/cost_format.hpp"
#include "bench_engine/report.hpp"
#include "bench_engine/yardstick.hpp"
#include "core/data_dir.hpp"
#include "core/input_file.hpp"
#include "bench_engine/svg_chart.hpp"
#include "cli/cli_common.hpp"
#include "cli/progress.hpp"
#include "write/package_writer.hpp"

namespace mb::cli {
namespace {

namespace fs = std::filesystem;

struct BenchArgs {
  std::vector<std::string> materials;
  std::vector<std::string> slots;
  std::vector<std::string> bricks;
  bool ibl = false;
  std::vector<uint32_t> lutSizes{16, 32, 64, 128};
  bench::BenchOptions options;
  std::string json, csv, outDir, markdown;
  std::string optimization = "2";  // -O, as compile's
  bool quiet = false;
};

// `bench` alone measures everything: every slot, the source tree's example materials, the
// IBL table. Any of --slot, --brick or MATERIAL narrows it to what is named (--ibl adds the
// IBL table back).
bench::BenchOptions resolveScope(const BenchArgs& a, const ShaderLibrary& lib, std::vector<std::string>& materials) {
  std::vector<std::string> slotNames;
  for (const auto& s : lib.slots()) slotNames.push_back(s.name);
  checkKnownNames(a.slots, slotNames, "E-UNKNOWN-SLOT", "slot");
  checkKnownNames(a.bricks, lib.brickIds(), "E-UNKNOWN-BRICK", "brick");
  bench::BenchOptions o = a.options;
  o.slots = a.slots;
  o.bricks = a.bricks;
  bool everything = a.slots.empty() && a.bricks.empty() && a.materials.empty();
  o.includeBricks = everything || !a.slots.empty() || !a.bricks.empty();
  if (everything || a.ibl) o.lutSizes = a.lutSizes;
  materials = a.materials;
  if (everything) {
    for (const auto& e : fs::directory_iterator(dataRoot() / "materials"))
      if (e.path().extension() == ".json") materials.push_back(e.path().string());
    std::sort(materials.begin(), materials.end());
  }
  return o;
}

// --markdown FILE: nothing when FILE does not exist (it is created, holding the marks);
// otherwise its text, which must hold both marks in order: only the part between them is
// matbricks', so a file without them is refused (E-MARKDOWN-NO-MARKS), never replaced whole.
std::string markedDocument(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return "";
  std::string text = readInputFileOrThrow(path, input_kind::kMarkdown);
  const size_t begin = text.find(bench::kMarkdownBegin);
  const size_t end = begin == std::string::npos ? std::string::npos : text.find(bench::kMarkdownEnd, begin);
  if (end == std::string::npos)
    throw DiagnosticError(
        {{Severity::Error,
          "E-MARKDOWN-NO-MARKS",
          {path, 0, 0},
          "'" + path + "' exists and lacks the marks '" + bench::kMarkdownBegin + "' ... '" + bench::kMarkdownEnd +
              "' (in that order): only the text between them is replaced, so a file without them is "
              "never overwritten; nothing was written",
          "put the two marks where the tables belong, or name a new file"}});
  return text;
}

// Before measuring: every output checked (docs/cli.md "Outputs"); --markdown is read and its
// generated part replaced, so it is the one output that may already hold the user's text.
void refuseUnsafeOutputs(const BenchArgs& a, const ShaderLibrary& lib, const std::vector<MaterialDesc>& materials) {
  std::vector<ProtectedPath> inputs = libraryInputs(lib);
  addMaterialInputs(inputs, materials);
  if (!a.outDir.empty()) {
    checkDirectoryOutput(a.outDir, inputs);
    inputs.push_back({a.outDir, "output directory"});
  }
  for (const auto& [file, what] : {std::pair{&a.json, "JSON results"}, std::pair{&a.csv, "CSV results"},
                                   std::pair{&a.markdown, "Markdown tables"}})
    if (!file->empty()) checkFileOutput(*file, what, inputs);
  if (!a.markdown.empty()) markedDocument(a.markdown);
}

// Costs as bench_engine/cost_format.hpp writes them (never 0 or negative: "below resolution"
// instead), each with its 95 % interval.
void printTable(const bench::BenchReport& r) {
  std::printf("device: %s\n%-18s %-44s %-17s %-26s %8s %7s %10s %10s  %-12s %s\n", r.device.c_str(), "group", "id",
              "cost/eval", "95% interval", "static", "instr", "max err", "mean err", "vs", "frontier");
  for (const auto& g : r.groups)
    for (const auto& it : g.items) {
      const bench::CostMeasurement& c = it.cost;
      std::string interval =
          c.resolved ? bench::formatDuration(c.nsPerEvalLow) + " to " + bench::formatDuration(c.nsPerEvalHigh)
                     : "< " + bench::formatDuration(c.nsUpperBound());
      std::string frontier = it.onFrontier ? "*" : it.tiedWith.empty() ? "" : "tie: " + it.tiedWith;
      std::printf("%-18s %-44s %-17s %-26s %8.1f %7zu %10.3g %10.3g  %-12s %s\n", g.name.c_str(), it.id.c_str(),
                  bench::formatCost(c).c_str(), interval.c_str(), it.staticCost, it.spirvInstructions,
                  it.error.maxScaled(), it.error.meanScaled(), it.yardstick.c_str(), frontier.c_str());
    }
  if (r.hasIbl)
    for (const auto& l : r.ibl.luts)
      std::printf("%-18s dfg_lut %3ux%-3u %-32s %-17s %-26s %8s %7s %10.3g %10.3g  %-12s\n", "ibl", l.size, l.size,
                  lut::lutFormatName(l.format).c_str(), "-", "-", "-", "-", l.error.maxScaled(), l.error.meanScaled(),
                  "ground_truth");
}

int runBench(const BenchArgs& a, const GlobalOptions& g) {
  ShaderLibrary lib = loadLibrary(g);
  std::vector<std::string> materialPaths;
  bench::BenchOptions o = resolveScope(a, lib, materialPaths);
  parseOptimizationLevel(a.optimization, o.cost.optimization);  // checked by CLI11
  std::vector<MaterialDesc> materials = loadMaterials(materialPaths, lib, g);
  if (a.materials.empty()) {
    // The shipped materials, not named by the user: skip those bench cannot measure (user
    // surface code has no C++ ground truth) with a note, rather than refuse the whole run.
    std::erase_if(materials, [&a](const MaterialDesc& m) {
      if (m.surface.present() && !a.quiet)
        std::fprintf(stderr, "%s: note: skipped: bench cannot measure user surface code\n", m.sourceFile.c_str());
      return m.surface.present();
    });
  }
  bench::refuseUnmeasurable(materials);
  refuseUnsafeOutputs(a, lib, materials);
  auto gpu = openDevice(g);
  Progress progress("bench", 0, a.quiet);  // runBench adds its units
  bench::BenchReport report = bench::runBench(lib, *gpu, materials, o, &progress);
  progress.finish();

  // Everything is rendered before anything is written; each file is written atomically.
  std::string json = bench::toJson(report).dump(2) + "\n", csv = bench::toCsv(report);
  std::string md = bench::toMarkdown(report), subtitle = bench::describeRun(report);
  if (!a.outDir.empty()) {
    PackageWriter w("bench");
    w.addFile("bench.json", json);
    w.addFile("bench.csv", csv);
    w.addFile("bench.md", md);
    for (const auto& grp : report.groups) w.addFile(grp.name + ".svg", bench::paretoSvg(grp, subtitle));
    w.commit(a.outDir);
  }
  if (!a.json.empty()) PackageWriter::writeFileAtomically(a.json, json);
  if (!a.csv.empty()) PackageWriter::writeFileAtomically(a.csv, csv);
  if (!a.markdown.empty())
    // Read again: the user may have edited it while the bench ran (checked again, too).
    PackageWriter::writeFileAtomically(a.markdown, bench::spliceGenerated(markedDocument(a.markdown), md));
  // -q: the results are in the files; nothing on stdout.
  if (!a.quiet) printTable(report);
  return reportLayerMessages(*gpu) ? kExitCheckFailed : kExitOk;
}

}  // namespace

Command addBenchCommand(CLI::App& app, GlobalOptions& g) {
  auto a = std::make_shared<BenchArgs>();
  CLI::App* cmd =
      app.add_subcommand("bench", "Run time against error: every brick per slot, material permutations, DFG LUTs");
  cmd->add_option("materials", a->materials,
                  std::string(kMaterialFilesHelp) + " (default with no --slot/--brick: the shipped materials/*.json)");
  cmd->add_option("--slot", a->slots, "Only the bricks of this slot (repeatable)");
  cmd->add_option("--brick", a->bricks, "Only this brick (repeatable)");
  cmd->add_flag("--ibl", a->ibl, "Also measure the DFG LUTs (implied when nothing is narrowed)");
  cmd->add_option("--lut-sizes", a->lutSizes, "DFG LUT sizes for the IBL table")
      ->delimiter(',')
      ->check(CLI::Range(2u, 1024u));
  cmd->add_option("--repeats", a->options.cost.repeats,
                  "Paired (timed, empty-loop) dispatches per item: median and 95% interval (>= 6 for one)")
      ->check(CLI::Range(1u, 1000u));
  cmd->add_option("--samples", a->options.samples, "Error samples per item")
      ->check(CLI::Range(uint64_t{1}, uint64_t{10000000}));
  cmd->add_option("--records", a->options.cost.records, "Records per timed dispatch (0: calibrate to --target-ms)")
      ->check(CLI::Range(uint64_t{0}, uint64_t{1} << 20));
  cmd->add_option(
         "--iterations", a->options.cost.iterations,
         "Evaluations per record in the bench probe (0: calibrate until the kernel clearly exceeds the empty loop)")
      ->check(CLI::Range(0u, bench::kMaxIterations));
  cmd->add_option("--target-ms", a->options.cost.targetDispatchMs, "Dispatch length the record calibration aims at")
      ->check(CLI::Range(0.1, 10000.0));
  cmd->add_option("--max-ms", a->options.cost.maxDispatchMs,
                  "Longest dispatch the iteration calibration may reach (0: 10 x --target-ms)")
      ->check(CLI::Range(0.0, 100000.0));
  cmd->add_option("--seed", a->options.seed, "Sampler seed");
  cmd->add_option("-O,--optimization", a->optimization,
                  "spirv-opt level of the timed kernels, as compile's -O0/-O1/-O2 (default 2): what a level costs at "
                  "run time")
      ->check(CLI::IsMember({"0", "1", "2", "O0", "O1", "O2"}));
  cmd->add_option("--json", a->json, "Write the full results as JSON");
  cmd->add_option("--csv", a->csv, "Write one CSV row per brick, permutation and LUT");
  cmd->add_option(
      "-o,--output-dir", a->outDir,
      "Write bench.json, bench.csv, bench.md and one SVG chart per group to this directory (new, empty or a matbricks output)");
  cmd->add_option("--markdown", a->markdown,
                  "Write the Markdown tables (replacing the generated part of an existing file)");
  cmd->add_flag("-q,--quiet", a->quiet, "No progress, no notes and no table on stdout (the files hold the results)");
  return {cmd, [a, &g] { return runBench(*a, g); }};
}

}  // namespace mb::cli
