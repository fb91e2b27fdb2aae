// matbricks stress: every brick, material or permutation over adversarial inputs (grazing
// and back-facing directions, n.h = 1, v = -l, unnormalized and zero vectors, extreme
// parameters), at fp32 and fp16. Fails (exit 1) on NaN/Inf in the declared domain.
#include <iostream>

#include "cli/cli_common.hpp"
#include "permute/permutation.hpp"
#include "stress/stress_report.hpp"
#include "write/package_writer.hpp"

namespace mb::cli {
namespace {

struct StressArgs {
  std::vector<std::string> materials;
  std::vector<std::string> bricks;
  bool allBricks = false;
  std::string precision = "fp32";
  std::string fp16 = "emulated";  // Fp16Mode
  uint64_t samples = 1024;
  uint64_t seed = 1;
  bool json = false;
  bool markdown = false;
  std::string output;
};

std::vector<Precision> precisions(const std::string& name) {
  if (name == "all") return allPrecisions();
  return {*parsePrecision(name)};  // checked by --precision's IsMember
}

// Builds the probe; at fp16 a brick that does not compile is a result, not an input error.
template <class Build>
bool tryBuild(ShaderPrecision p, Build build, ProbeProgram& program, StressResult& failed) {
  if (p == ShaderPrecision::Fp32) {
    program = build();
    return true;
  }
  try {
    program = build();
    return true;
  } catch (const DiagnosticError& e) {
    failed.precision = p;
    failed.compileError = e.diagnostics().empty() ? e.what() : formatDiagnostic(e.diagnostics().front());
    return false;
  }
}

int runStress(const StressArgs& a, const GlobalOptions& g) {
  setFp16Mode(*parseFp16Mode(a.fp16));
  if (a.materials.empty() && a.bricks.empty() && !a.allBricks)
    throw CLI::ValidationError("stress", "give MATERIAL files, --brick ID or --all-bricks");
  if (!a.output.empty() && !a.markdown) throw CLI::ValidationError("stress", "-o needs --markdown");
  ShaderLibrary lib = loadLibrary(g);
  std::vector<MaterialDesc> materials = loadMaterials(a.materials, lib, g);
  std::vector<const Brick*> bricks;
  if (a.allBricks)
    for (const auto& b : lib.bricks()) bricks.push_back(&b);
  for (const auto& id : a.bricks) {
    const Brick* b = lib.findBrick(id);
    if (!b)
      throw DiagnosticError({{Severity::Error,
                              "E-UNKNOWN-BRICK",
                              {"<command line>", 0, 0},
                              "unknown brick '" + id + "'",
                              didYouMean(id, lib.brickIds())}});
    bricks.push_back(b);
  }
  if (!a.output.empty()) {
    std::vector<ProtectedPath> inputs = libraryInputs(lib);
    addMaterialInputs(inputs, materials);
    checkFileOutput(a.output, "report", inputs);
  }
  auto gpu = openDevice(g);
  StressOptions options;
  options.randomSamples = a.samples;
  options.seed = a.seed;

  std::vector<StressResult> results;
  for (Precision axis : precisions(a.precision)) {
    const ShaderPrecision p = shaderPrecision(axis);
    for (const Brick* b : bricks) {
      ProbeProgram program;
      StressResult failed;
      failed.key = "brick." + b->id + (p == ShaderPrecision::Fp16 ? ".fp16" : "");
      failed.kind = "brick";
      failed.id = b->id;
      if (tryBuild(
              p, [&] { return buildBrickProbe(lib, *b, false, p); }, program, failed)) {
        results.push_back(stressProbe(*gpu, program, "brick", b->id, options));
      } else {
        results.push_back(failed);
      }
    }
    for (size_t m = 0; m < materials.size(); ++m) {
      Permutation perm;
      perm.material = &materials[m];
      perm.precision = axis;
      ProbeProgram program;
      StressResult failed;
      // One file can hold many materials (glTF): each is named by its own source file and
      // name, never by its position in the argument list.
      const MaterialDesc& material = materials[m];
      failed.key = perm.key();
      failed.kind = "permutation";
      failed.id = material.sourceFile;
      if (tryBuild(
              p, [&] { return buildPermutationProbe(lib, perm, /*illuminanceInput=*/true); }, program, failed))
        results.push_back(stressProbe(*gpu, program, "permutation", material.sourceFile, options));
      else
        results.push_back(failed);
      results.back().materialName = material.name;
    }
  }

  const std::string cli = "matbricks" + (g.shaderlib.empty() ? std::string() : " --shaderlib " + g.shaderlib);
  bool allPassed = true;
  for (const auto& r : results) allPassed = allPassed && r.passed();
  if (a.markdown) {
    std::string command = "matbricks stress";
    for (const auto& m : a.materials) command += " " + m;
    for (const auto& id : a.bricks) command += " --brick " + id;
    command += std::string(a.allBricks ? " --all-bricks" : "") + " --precision " + a.precision +
               (a.fp16 == "driver" ? " --fp16 driver" : "") + " --markdown";
    std::string md =
        formatStressMarkdown(results, command + (a.output.empty() ? "" : " -o " + a.output), gpu->deviceName());
    if (a.output.empty())
      std::cout << md;
    else
      PackageWriter::writeFileAtomically(a.output, md);
  } else if (a.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& r : results) out.push_back(toJson(r, cli));
    std::cout << out.dump(2) << "\n";
  } else {
    std::cout << "device: " << gpu->deviceName() << "\n" << formatStressTable(results);
    for (const auto& r : results) {
      if (r.passed() || !r.compileError.empty()) continue;
      std::cout << "\n"
                << r.key << ": NaN/Inf in the declared domain; worst input:\n"
                << csvRow(r.columns, r.worstInDomainRow) << "replay: " << replayCommand(r, cli, true) << "\n";
    }
  }
  bool layerMessages = reportLayerMessages(*gpu);
  return allPassed && !layerMessages ? kExitOk : kExitCheckFailed;
}

}  // namespace

Command addStressCommand(CLI::App& app, GlobalOptions& g) {
  auto args = std::make_shared<StressArgs>();
  CLI::App* cmd =
      app.add_subcommand("stress", "Run bricks and materials over adversarial inputs; fail on NaN/Inf in their domain");
  cmd->add_option("materials", args->materials, kMaterialFilesHelp);
  cmd->add_option("--brick", args->bricks, "Stress this brick (repeatable)");
  cmd->add_flag("--all-bricks", args->allBricks, "Stress every brick of the library");
  cmd->add_option("--precision", args->precision, "fp32, fp16 (half arithmetic, see --fp16) or all")
      ->check(CLI::IsMember({"fp32", "fp16", "all"}));
  cmd->add_option(
         "--fp16", args->fp16,
         "How fp16 kernels compute: emulated (default; the least precise conforming device: half rounding, flushed denormals, division by the reciprocal, transcendentals at their spec error bounds) or driver (the device's own half arithmetic; needs shaderFloat16). docs/fp16.md")
      ->check(CLI::IsMember({"emulated", "driver"}));
  cmd->add_option("--samples", args->samples, "Validation-sampler records added to the adversarial set")
      ->check(CLI::Range(uint64_t{0}, uint64_t{10000000}));
  cmd->add_option("--seed", args->seed, "Sampler seed");
  cmd->add_flag("--json", args->json, "One JSON record per brick or permutation, with replay commands");
  cmd->add_flag("--markdown", args->markdown, "The per-brick error table as Markdown (docs/fp16.md)");
  cmd->add_option("-o,--output", args->output, "With --markdown: write to this file (atomically)");
  return {cmd, [args, &g] { return runStress(*args, g); }};
}

}  // namespace mb::cli
