// matbricks eval: evaluate one brick or one material at user-given inputs on the GPU and
// with the double reference, and print both with the error.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/cli_common.hpp"
#include "load/csv_table.hpp"
#include "permute/permutation.hpp"
#include "validate/probe_program.hpp"

namespace mb::cli {
namespace {

struct EvalArgs {
  std::string brick;
  std::string material;
  std::string name;  // which material of the file; empty: the first
  std::string input;
  bool json = false;
  std::string precision = "fp32";
  std::string fp16 = "emulated";  // Fp16Mode
};

// --name picks one material of a file that holds several (glTF); without it, the first.
MaterialDesc pickMaterial(const std::vector<MaterialDesc>& materials, const EvalArgs& a) {
  if (a.name.empty()) return materials.front();
  std::vector<std::string> names;
  for (const auto& m : materials) {
    if (m.name == a.name) return m;
    names.push_back(m.name);
  }
  throw DiagnosticError({{Severity::Error,
                          "E-UNKNOWN-MATERIAL",
                          {a.material, 0, 0},
                          "no material named '" + a.name + "' in this file",
                          didYouMean(a.name, names)}});
}

// Rows evaluated per GPU dispatch: memory stays constant however long the CSV is (its
// inputs, outputs, references and conditioning: ~100 bytes per value).
constexpr size_t kRowsPerChunk = size_t{1} << 16;

// Prints each row as it is evaluated, as text or as the elements of a JSON "rows" array.
class EvalPrinter {
 public:
  EvalPrinter(const ProbeProgram& program, bool json) : program_(program), json_(json) {}

  void begin(const std::string& deviceName) {
    if (json_)
      std::printf("{\n  \"key\": %s,\n  \"rows\": [", nlohmann::json(program_.shader.key).dump().c_str());
    else
      std::printf("%s on %s\n", program_.shader.key.c_str(), deviceName.c_str());
  }

  void rows(const ProbeRun& run, const std::vector<int>& lines) {
    for (uint64_t i = 0; i < run.count; ++i) json_ ? jsonRow(run, i, lines[i]) : textRow(run, i, lines[i]);
  }

  void end(const ErrorStats& stats) {
    if (json_) {
      std::printf("%s],\n  \"passed\": %s\n}\n", printed_ ? "\n  " : "", stats.passed() ? "true" : "false");
      return;
    }
    std::printf("%s: max_abs=%.4g max_rel=%.4g nan=%llu inf=%llu (tolerance abs %.3g + rel %.3g)\n",
                stats.passed() ? "within tolerance" : "OUT OF TOLERANCE", stats.maxAbs, stats.maxRel,
                static_cast<unsigned long long>(stats.nanCount), static_cast<unsigned long long>(stats.infCount),
                program_.tolerance.abs, program_.tolerance.rel);
  }

 private:
  void jsonRow(const ProbeRun& run, uint64_t i, int line) {
    const ProbeLayout& layout = program_.shader.layout;
    const uint32_t os = layout.outStride, is = layout.inStride;
    nlohmann::json row{{"line", line}};
    for (uint32_t k = 0; k < is; ++k) row["inputs"][inCols_[k]] = run.inputs[i * is + k];
    for (uint32_t k = 0; k < os; ++k) {
      double gv = run.gpu[i * os + k], rv = run.reference[i * os + k];
      row["gpu"][outCols_[k]] = std::isfinite(gv) ? nlohmann::json(gv) : nlohmann::json(std::to_string(gv));
      row["reference"][outCols_[k]] = std::isfinite(rv) ? nlohmann::json(rv) : nlohmann::json(std::to_string(rv));
      row["abs_error"][outCols_[k]] =
          std::isfinite(gv - rv) ? nlohmann::json(std::abs(gv - rv)) : nlohmann::json("nan");
    }
    std::printf("%s\n    %s", printed_++ ? "," : "", row.dump().c_str());
  }

  void textRow(const ProbeRun& run, uint64_t i, int line) {
    const ProbeLayout& layout = program_.shader.layout;
    const uint32_t os = layout.outStride, is = layout.inStride;
    std::printf("row %llu (line %d):", static_cast<unsigned long long>(++printed_), line);
    for (uint32_t k = 0; k < is; ++k) std::printf(" %s=%.9g", inCols_[k].c_str(), run.inputs[i * is + k]);
    std::printf("\n");
    for (uint32_t k = 0; k < os; ++k) {
      double gv = run.gpu[i * os + k], rv = run.reference[i * os + k];
      std::printf("  %-6s gpu=%-16.9g reference=%-22.17g abs_err=%-12.4g rel_err=%.4g\n", outCols_[k].c_str(), gv, rv,
                  std::abs(gv - rv), std::abs(gv - rv) / std::max(std::abs(rv), kRelativeErrorFloor));
    }
  }

  const ProbeProgram& program_;
  bool json_;
  std::vector<std::string> inCols_ = program_.shader.layout.columns();
  std::vector<std::string> outCols_ = program_.shader.layout.outputColumns();
  uint64_t printed_ = 0;
};

// The rows of the CSV in chunks, their columns in the probe's order, as fp32 inputs.
class EvalRows {
 public:
  EvalRows(CsvReader& reader, const std::vector<size_t>& order) : reader_(reader), order_(order) {}
  // The next chunk into `inputs` and `lines`; false when there are no rows left.
  bool next(std::vector<float>& inputs, std::vector<int>& lines) {
    inputs.clear();
    lines.clear();
    int line = 0;
    while (lines.size() < kRowsPerChunk && reader_.next(row_, line)) {
      for (size_t column : order_) inputs.push_back(static_cast<float>(row_[column]));
      lines.push_back(line);
    }
    return !lines.empty();
  }

 private:
  CsvReader& reader_;
  const std::vector<size_t>& order_;
  std::vector<double> row_;
};

int runEval(const EvalArgs& a, const GlobalOptions& g) {
  setFp16Mode(*parseFp16Mode(a.fp16));
  if (a.brick.empty() == a.material.empty())
    throw CLI::ValidationError("eval", "give exactly one of --brick ID or --material FILE");
  ShaderLibrary lib = loadLibrary(g);
  std::vector<MaterialDesc> materials;
  ProbeProgram program;
  // The CSV is read twice, row by row: once to check every row before anything is printed
  // (a bad row is a coded error and no output), once to evaluate it in chunks.
  CsvReader check = CsvReader::open(a.input);
  const std::vector<std::string>& header = check.header().names;
  if (!a.brick.empty()) {
    const Brick* b = lib.findBrick(a.brick);
    if (!b) {
      throw DiagnosticError({{Severity::Error,
                              "E-UNKNOWN-BRICK",
                              {"<command line>", 0, 0},
                              "unknown brick '" + a.brick + "'",
                              didYouMean(a.brick, lib.brickIds())}});
    }
    program = buildBrickProbe(lib, *b, false, shaderPrecision(*parsePrecision(a.precision)));
  } else {
    // `materials` outlives the probe build: the permutation points into it.
    materials = {pickMaterial(loadMaterials({a.material}, lib, g), a)};
    Permutation perm = permutationsFor(materials).front();
    perm.precision = *parsePrecision(a.precision);  // checked by --precision's IsMember
    // An illuminance column (illuminance.x, .y, .z) is optional; without it the light has
    // unit illuminance. `stress` prints such columns in its replay rows.
    program =
        buildPermutationProbe(lib, perm, std::find(header.begin(), header.end(), "illuminance.x") != header.end());
  }
  const std::vector<size_t> order = columnOrder(check.header(), program.shader.layout.columns());
  {
    std::vector<double> row;
    int line = 0;
    while (check.next(row, line)) {
    }
    check.throwIfErrors();
  }

  auto gpu = openDevice(g);
  EvalPrinter printer(program, a.json);
  printer.begin(gpu->deviceName());
  CsvReader reader = CsvReader::open(a.input);
  EvalRows rows(reader, order);
  ErrorStats stats;
  std::vector<float> inputs;
  std::vector<int> lines;
  for (uint64_t first = 0; rows.next(inputs, lines); first += lines.size()) {
    const ProbeRun run = runProbe(*gpu, program, std::move(inputs));
    addErrors(stats, run, program, first);
    printer.rows(run, lines);
    inputs = {};
  }
  // Only a file changed between the two readings can fail here.
  reader.throwIfErrors();
  printer.end(stats);
  bool layerMessages = reportLayerMessages(*gpu);
  return stats.passed() && !layerMessages ? kExitOk : kExitCheckFailed;
}

}  // namespace

Command addEvalCommand(CLI::App& app, GlobalOptions& g) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* cmd = app.add_subcommand(
      "eval", "Evaluate a brick or a material at inputs from a CSV file, on the GPU and with the reference");
  cmd->add_option("--brick", args->brick, "Brick id (see `matbricks bricks`)");
  cmd->add_option("--material", args->material, std::string(kMaterialFilesHelp) + "; one file");
  cmd->add_option("--name", args->name, "With --material: the material of that name in the file (default: its first)");
  cmd->add_option("--input", args->input, "CSV file; header = the probe's input names (see `bricks --json`)")
      ->required();
  cmd->add_flag("--json", args->json, "JSON output");
  cmd->add_option("--precision", args->precision, "fp32, or fp16 (half arithmetic, see --fp16; only NaN/Inf fail)")
      ->check(CLI::IsMember({"fp32", "fp16"}));
  cmd->add_option(
         "--fp16", args->fp16,
         "How fp16 kernels compute: emulated (default; the least precise conforming device: half rounding, flushed denormals, division by the reciprocal, transcendentals at their spec error bounds) or driver (the device's own half arithmetic; needs shaderFloat16). docs/fp16.md")
      ->check(CLI::IsMember({"emulated", "driver"}));
  return {cmd, [args, &g] { return runEval(*args, g); }};
}

}  // namespace mb::cli
