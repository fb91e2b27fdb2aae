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

int runEval(const EvalArgs& a, const GlobalOptions& g) {
  setFp16Mode(*parseFp16Mode(a.fp16));
  if (a.brick.empty() == a.material.empty())
    throw CLI::ValidationError("eval", "give exactly one of --brick ID or --material FILE");
  ShaderLibrary lib = loadLibrary(g);
  std::vector<MaterialDesc> materials;
  ProbeProgram program;
  CsvTable table = loadCsv(a.input);
  if (!a.brick.empty()) {
    const Brick* b = lib.findBrick(a.brick);
    if (!b) {
      throw DiagnosticError({{Severity::Error,
                              "E-UNKNOWN-BRICK",
                              {"<command line>", 0, 0},
                              "unknown brick '" + a.brick + "'",
                              didYouMean(a.brick, lib.brickIds())}});
    }
    program = buildBrickProbe(lib, *b, false, *parsePrecision(a.precision));
  } else {
    // `materials` outlives the probe build: the permutation points into it.
    materials = {pickMaterial(loadMaterials({a.material}, lib, g), a)};
    Permutation perm = permutationsFor(materials).front();
    perm.precision = a.precision;
    // An illuminance column (illuminance.x, .y, .z) is optional; without it the light has
    // unit illuminance. `stress` prints such columns in its replay rows.
    program = buildPermutationProbe(
        lib, perm, std::find(table.header.begin(), table.header.end(), "illuminance.x") != table.header.end());
  }
  const ProbeLayout& layout = program.shader.layout;
  std::vector<std::vector<double>> rows = selectColumns(table, layout.columns());
  std::vector<float> inputs;
  for (const auto& r : rows)
    for (double v : r) inputs.push_back(static_cast<float>(v));

  auto gpu = openDevice(g);
  ProbeRun run = runProbe(*gpu, program, std::move(inputs));
  ErrorStats stats = compare(run, program);

  auto inCols = layout.columns();
  auto outCols = layout.outputColumns();
  uint32_t os = layout.outStride, is = layout.inStride;
  if (a.json) {
    nlohmann::json out{{"key", program.shader.key}, {"rows", nlohmann::json::array()}};
    for (uint64_t i = 0; i < run.count; ++i) {
      nlohmann::json row{{"line", table.rowLines[i]}};
      for (uint32_t k = 0; k < is; ++k) row["inputs"][inCols[k]] = run.inputs[i * is + k];
      for (uint32_t k = 0; k < os; ++k) {
        double gv = run.gpu[i * os + k], rv = run.reference[i * os + k];
        row["gpu"][outCols[k]] = std::isfinite(gv) ? nlohmann::json(gv) : nlohmann::json(std::to_string(gv));
        row["reference"][outCols[k]] = std::isfinite(rv) ? nlohmann::json(rv) : nlohmann::json(std::to_string(rv));
        row["abs_error"][outCols[k]] =
            std::isfinite(gv - rv) ? nlohmann::json(std::abs(gv - rv)) : nlohmann::json("nan");
      }
      out["rows"].push_back(row);
    }
    out["passed"] = stats.passed();
    std::cout << out.dump(2) << "\n";
  } else {
    std::printf("%s on %s\n", program.shader.key.c_str(), gpu->deviceName().c_str());
    for (uint64_t i = 0; i < run.count; ++i) {
      std::printf("row %llu (line %d):", static_cast<unsigned long long>(i + 1), table.rowLines[i]);
      for (uint32_t k = 0; k < is; ++k) std::printf(" %s=%.9g", inCols[k].c_str(), run.inputs[i * is + k]);
      std::printf("\n");
      for (uint32_t k = 0; k < os; ++k) {
        double gv = run.gpu[i * os + k], rv = run.reference[i * os + k];
        std::printf("  %-6s gpu=%-16.9g reference=%-22.17g abs_err=%-12.4g rel_err=%.4g\n", outCols[k].c_str(), gv, rv,
                    std::abs(gv - rv), std::abs(gv - rv) / std::max(std::abs(rv), kRelativeErrorFloor));
      }
    }
    std::printf("%s: max_abs=%.4g max_rel=%.4g nan=%llu inf=%llu (tolerance abs %.3g + rel %.3g)\n",
                stats.passed() ? "within tolerance" : "OUT OF TOLERANCE", stats.maxAbs, stats.maxRel,
                static_cast<unsigned long long>(stats.nanCount), static_cast<unsigned long long>(stats.infCount),
                program.tolerance.abs, program.tolerance.rel);
  }
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
