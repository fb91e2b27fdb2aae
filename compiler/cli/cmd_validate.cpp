// matbricks validate: run probes on the GPU against the double references.
#include <cstdio>
#include <iostream>

#include "cli/cli_common.hpp"
#include "cli/progress.hpp"
#include "glrun/gl_compute.hpp"
#include "permute/axes.hpp"
#include "validate/probe_language.hpp"
#include "validate/validation.hpp"

namespace mb::cli {
namespace {

struct ValidateArgs {
  std::vector<std::string> materials;
  std::vector<std::string> bricks;
  bool allBricks = false;
  bool unstable = false;
  uint64_t samples = 4096;
  uint64_t seed = 1;
  bool json = false;
  bool quiet = false;
  std::string precision = "fp32";
  std::string fp16 = "emulated";          // Fp16Mode
  std::string target = "spirv";           // the language executed (validate/probe_language.hpp)
  std::vector<std::string> lights;        // empty: every light type the model shades
  std::vector<std::string> environments;  // empty: every environment mode it supports
};

int runValidate(const ValidateArgs& a, const GlobalOptions& g) {
  setFp16Mode(*parseFp16Mode(a.fp16));
  if (a.materials.empty() && a.bricks.empty() && !a.allBricks)
    throw CLI::ValidationError("validate", "give MATERIAL files, --brick ID or --all-bricks");
  ShaderLibrary lib = loadLibrary(g);
  std::vector<MaterialDesc> materials = loadMaterials(a.materials, lib, g);
  std::vector<const Brick*> bricks;
  if (a.allBricks) {
    for (const auto& b : lib.bricks()) bricks.push_back(&b);
  }
  for (const auto& id : a.bricks) {
    const Brick* b = lib.findBrick(id);
    if (!b) {
      throw DiagnosticError({{Severity::Error,
                              "E-UNKNOWN-BRICK",
                              {"<command line>", 0, 0},
                              "unknown brick '" + id + "'",
                              didYouMean(id, lib.brickIds())}});
    }
    bricks.push_back(b);
  }
  const ProbeLanguage language = *parseProbeLanguage(a.target);
  // spirv and hlsl run on Vulkan, glsl450 and essl310 on OpenGL (4.5 core, ES 3.1) through EGL.
  std::unique_ptr<harness::VulkanHarness> gpu;
  std::unique_ptr<gl::GlCompute> glContext;
  if (runsOnVulkan(language))
    gpu = openDevice(g);
  else
    glContext =
        std::make_unique<gl::GlCompute>(language == ProbeLanguage::Essl310 ? gl::GlApi::Es31 : gl::GlApi::Gl45Core);
  const ProbeDevices devices{gpu.get(), glContext.get()};
  const Precision axis = *parsePrecision(a.precision);  // checked by --precision's IsMember
  const ShaderPrecision precision = shaderPrecision(axis);

  std::vector<Permutation> perms;
  for (const auto& m : materials) {
    std::vector<std::string> notes;
    for (auto& perm :
         permutationsToValidate(m, lib, parseLightTypes(a.lights), parseEnvironmentModes(a.environments), axis, notes))
      perms.push_back(std::move(perm));
    if (!a.quiet)
      for (const auto& n : notes) std::fprintf(stderr, "%s: note: %s\n", m.sourceFile.c_str(), n.c_str());
  }
  size_t units = bricks.size() + perms.size();
  if (a.unstable)
    for (const Brick* b : bricks) units += !b->unstableFile.empty();
  Progress progress("validate", units, a.quiet, a.json);

  std::vector<ValidationRecord> records, unstableRecords;
  for (const Brick* b : bricks) {
    records.push_back(
        validateProbe(devices, buildBrickProbeIn(lib, *b, false, precision, language), "brick", a.samples, a.seed));
    progress.advance();
    if (a.unstable && !b->unstableFile.empty()) {
      // Expected to fail: it shows the problem the shipped form fixes. Reported, not judged.
      unstableRecords.push_back(validateProbe(devices, buildBrickProbeIn(lib, *b, true, precision, language),
                                              "unstable_variant", a.samples, a.seed));
      progress.advance();
    }
  }
  for (const auto& perm : perms) {
    records.push_back(
        validateProbe(devices, buildPermutationProbeIn(lib, perm, language), "permutation", a.samples, a.seed));
    progress.advance();
  }
  progress.finish();

  bool allPassed = true;
  for (const auto& r : records) allPassed = allPassed && r.passed();
  if (a.quiet && allPassed && !a.json) {
    // -q: nothing on success; the exit code says it.
  } else if (a.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto* list : {&records, &unstableRecords})
      for (const auto& r : *list) {
        out.push_back(toJson(r));
        // Records of the default target are as before; another target's say which it is.
        if (language != ProbeLanguage::Spirv) out.back()["target"] = a.target;
      }
    std::cout << out.dump(2) << "\n";
  } else {
    std::cout << "device: " << (gpu ? gpu->deviceName() : glContext->deviceName())
              << (language == ProbeLanguage::Spirv ? "" : " (target " + a.target + ")") << "\n"
              << formatValidationTable(records);
    for (const auto& r : records)
      if (!r.passed()) std::cout << "worst input of " << r.key << ": " << r.worstInput << "\n";
    if (!unstableRecords.empty()) {
      std::cout << "\nunstable variants (the naive forms the shipped bricks replace; not judged):\n"
                << formatValidationTable(unstableRecords);
    }
  }
  bool layerMessages = gpu && reportLayerMessages(*gpu);
  return allPassed && !layerMessages ? kExitOk : kExitCheckFailed;
}

}  // namespace

Command addValidateCommand(CLI::App& app, GlobalOptions& g) {
  auto args = std::make_shared<ValidateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "validate", "Run permutations and bricks on the GPU and compare with the double-precision references");
  cmd->add_option("materials", args->materials, kMaterialFilesHelp);
  cmd->add_option("--brick", args->bricks, "Validate this brick (repeatable)");
  cmd->add_flag("--all-bricks", args->allBricks, "Validate every brick of the library");
  cmd->add_flag("--unstable-variants", args->unstable,
                "Also run each brick's naive form (if it has one) to show the problem its stable form fixes");
  cmd->add_option("--samples", args->samples, "Samples per permutation or brick")
      ->check(CLI::Range(uint64_t{1}, uint64_t{50000000}));
  cmd->add_option("--seed", args->seed, "Sampler seed");
  cmd->add_flag("--json", args->json, "One JSON record per permutation or brick");
  cmd->add_flag("-q,--quiet", args->quiet,
                "No progress and no notes; without --json, print the table only when a check fails");
  cmd->add_option(
         "--precision", args->precision,
         "fp32, or fp16: half arithmetic, see --fp16 on the fp16 domain; errors are reported, only NaN/Inf fail (docs/fp16.md)")
      ->check(CLI::IsMember({"fp32", "fp16"}));
  cmd->add_option(
         "--fp16", args->fp16,
         "How fp16 kernels compute: emulated (default; the least precise conforming device: half rounding, flushed denormals, division by the reciprocal, transcendentals at their spec error bounds) or driver (the device's own half arithmetic; needs shaderFloat16). docs/fp16.md")
      ->check(CLI::IsMember({"emulated", "driver"}));
  cmd->add_option("--target", args->target,
                  "Language the probes run in: spirv (default; Vulkan), hlsl (glslang's HLSL front end, then Vulkan), "
                  "glsl450 or essl310 (Mesa's GLSL compiler, OpenGL 4.5 core / ES 3.1 through EGL). docs/targets.md")
      ->check(CLI::IsMember(executableLanguages()));
  cmd->add_option("--lights", args->lights,
                  "Light types shaded together in each material permutation (default: all the model shades)")
      ->delimiter(',')
      ->check(CLI::IsMember(allLightTypeNames()));
  cmd->add_option("--environment", args->environments,
                  "Environment modes to validate, one permutation each (default: all the model supports)")
      ->delimiter(',')
      ->check(CLI::IsMember(allEnvironmentModeNames()));
  return {cmd, [args, &g] { return runValidate(*args, g); }};
}

}  // namespace mb::cli
