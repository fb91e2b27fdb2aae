// Every language `compile --targets` writes is executed, not only re-parsed: HLSL through
// glslang's HLSL front end on lavapipe, GLSL 450 and ESSL 3.10 through Mesa's own GLSL
// compiler on llvmpipe (OpenGL 4.5 core and ES 3.1 contexts on EGL's surfaceless platform),
// each against the same double reference and tolerance as the SPIR-V (docs/targets.md
// "Executed").
#include <catch2/catch.hpp>

#include <algorithm>
#include <regex>

#include "compile/hlsl_spirv.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"
#include "validate/probe_language.hpp"
#include "validate/validation.hpp"

using namespace mb;

namespace {

// One device of each kind for the whole test binary, opened when first needed (a test of the GL
// languages alone needs no Vulkan device): the driver's first compile of a kernel is the costly
// part, and each device keeps the kernels it compiled.
harness::VulkanHarness& vulkan() {
  static harness::VulkanHarness gpu(harness::testDeviceOptions());
  return gpu;
}

gl::GlCompute& glContext(gl::GlApi api) {
  static gl::GlCompute gl45(gl::GlApi::Gl45Core), es31(gl::GlApi::Es31);
  return api == gl::GlApi::Es31 ? es31 : gl45;
}

ProbeDevices devicesFor(ProbeLanguage language) {
  if (runsOnVulkan(language)) return {&vulkan(), nullptr};
  return {nullptr, &glContext(language == ProbeLanguage::Essl310 ? gl::GlApi::Es31 : gl::GlApi::Gl45Core)};
}

const std::vector<ProbeLanguage> kTranslated = {ProbeLanguage::Hlsl, ProbeLanguage::Glsl450, ProbeLanguage::Essl310};

// The languages that run fp16 here: glsl450 needs GL_AMD_gpu_shader_half_float, which llvmpipe
// lacks (checked below).
std::vector<ProbeLanguage> languagesAt(Precision precision) {
  if (precision == Precision::Fp32) return kTranslated;
  return {ProbeLanguage::Hlsl, ProbeLanguage::Essl310};
}

// Validates `perm` in `language`, checking it against the SPIR-V on the same records.
void checkPermutation(const ShaderLibrary& lib, const Permutation& perm, ProbeLanguage language, uint64_t samples) {
  LanguageProbe p = buildPermutationProbeIn(lib, perm, language);
  ValidationRecord r = validateProbe(devicesFor(language), p, "permutation", samples, 11);
  INFO(languageName(language) << " " << r.key << " (" << p.arithmetic() << "): max_abs " << r.stats.maxAbs
                              << " max_rel " << r.stats.maxRel << " failures " << r.stats.failures << " worst "
                              << r.worstInput);
  CHECK(r.stats.components == samples * p.program.shader.layout.outStride);
  CHECK(r.stats.nanCount == 0);
  CHECK(r.stats.infCount == 0);
  CHECK(r.passed());
}

Permutation permutationOf(const MaterialDesc& m, std::vector<LightType> lights, EnvironmentMode environment,
                          Precision precision) {
  Permutation perm;
  perm.material = &m;
  perm.lights = std::move(lights);
  perm.environment = environment;
  perm.precision = precision;
  return perm;
}

}  // namespace

TEST_CASE("validate --target names the executable languages, spirv first", "[languages]") {
  CHECK(executableLanguages() == std::vector<std::string>{"spirv", "hlsl", "glsl450", "essl310"});
  CHECK(parseProbeLanguage("glsl450") == ProbeLanguage::Glsl450);
  CHECK(!parseProbeLanguage("msl"));
  CHECK(runsOnVulkan(ProbeLanguage::Hlsl));
  CHECK(!runsOnVulkan(ProbeLanguage::Essl310));
}

TEST_CASE("the HLSL push-constant block is marked for Vulkan, once, or refused", "[languages]") {
  const std::string hlsl = "ByteAddressBuffer a : register(t0, space0);\ncbuffer MbPush\n{\n    uint c;\n};\n";
  CHECK(hlslWithPushConstantBlock(hlsl, "k.glsl").find("\n[[vk::push_constant]] cbuffer MbPush\n") !=
        std::string::npos);
  CHECK_THROWS_AS(hlslWithPushConstantBlock("cbuffer Other\n{\n};\n", "k.glsl"), DiagnosticError);
  CHECK_THROWS_AS(hlslWithPushConstantBlock(hlsl + hlsl, "k.glsl"), DiagnosticError);
}

TEST_CASE("a representative permutation validates in every executable language", "[languages][vulkan][gl]") {
  // The default run: the standard model (filament_plastic) and the cloth model (velvet_green),
  // each with every light its model shades, in one environment, fp32 in three languages and
  // fp16 in the two that run it. The full material x lights x environment x language sweep is
  // the hidden test below (CTest `languages_sweep`, label sweep).
  const ShaderLibrary& lib = test::shippedLibrary();
  for (const char* name : {"filament_plastic", "velvet_green"}) {
    const MaterialDesc m = test::shippedMaterial(name);
    const std::vector<Permutation> perms = validationPermutationsFor(m, lib);
    REQUIRE(!perms.empty());
    for (Precision precision : allPrecisions()) {
      Permutation perm = perms.front();
      perm.precision = precision;
      for (ProbeLanguage language : languagesAt(precision)) checkPermutation(lib, perm, language, 1024);
    }
  }
}

namespace {

// The sweep of one language: every shipped material, every environment mode its model supports,
// with every light type alone and all of them together (validate's default), at fp32 and, where
// the language runs it, fp16.
void sweepLanguage(ProbeLanguage language) {
  const ShaderLibrary& lib = test::shippedLibrary();
  for (const auto& file : test::exampleMaterialFiles()) {
    const MaterialDesc m = loadMaterialJson(file, lib);
    for (const Permutation& perm : validationPermutationsFor(m, lib)) {
      std::vector<std::vector<LightType>> lightSets = {perm.lights};
      for (LightType light : perm.lights) lightSets.push_back({light});
      for (const auto& lights : lightSets)
        for (Precision precision : allPrecisions()) {
          const auto at = languagesAt(precision);
          if (std::find(at.begin(), at.end(), language) == at.end()) continue;
          checkPermutation(lib, permutationOf(m, lights, perm.environment, precision), language, 1024);
        }
    }
  }
}

}  // namespace

// One hidden test per language, so that CTest runs them side by side (languages_sweep_*).
TEST_CASE("every shipped material in every light set and environment, in HLSL", "[.languages-sweep-hlsl][vulkan][gl]") {
  sweepLanguage(ProbeLanguage::Hlsl);
}

TEST_CASE("every shipped material in every light set and environment, in GLSL 450",
          "[.languages-sweep-glsl450][vulkan][gl]") {
  sweepLanguage(ProbeLanguage::Glsl450);
}

TEST_CASE("every shipped material in every light set and environment, in ESSL 3.10",
          "[.languages-sweep-essl310][vulkan][gl]") {
  sweepLanguage(ProbeLanguage::Essl310);
}

TEST_CASE("glsl450 at fp16 is refused on llvmpipe with the missing extension named", "[languages][gl]") {
  // SPIRV-Cross writes desktop GLSL's 16-bit floats with GL_AMD_gpu_shader_half_float; llvmpipe
  // does not offer it, so the fp16 glsl450 kernel cannot run here. If a Mesa update adds it, this
  // test fails and the fp16 glsl450 runs should join the sweep.
  REQUIRE(!glContext(gl::GlApi::Gl45Core).hasExtension("GL_AMD_gpu_shader_half_float"));
  const ShaderLibrary& lib = test::shippedLibrary();
  const MaterialDesc m = test::shippedMaterial("filament_plastic");
  LanguageProbe p = buildPermutationProbeIn(
      lib, permutationOf(m, {LightType::Dir}, EnvironmentMode::None, Precision::Fp16), ProbeLanguage::Glsl450);
  CHECK(p.source.find("#extension GL_AMD_gpu_shader_half_float") != std::string::npos);
  CHECK_THROWS_WITH(runProbeOn(devicesFor(ProbeLanguage::Glsl450), p, {}),
                    Catch::Contains("lacks GL_AMD_gpu_shader_half_float"));
}

TEST_CASE("a wrong translation is caught in every executable language", "[languages][vulkan][gl]") {
  // Negative control: the emitted source with one constant of the shading changed (pi written
  // as 3.2) must fail validation, so the runs above can fail when a language computes something
  // else.
  const ShaderLibrary& lib = test::shippedLibrary();
  const MaterialDesc m = test::shippedMaterial("filament_plastic");
  const Permutation perm = permutationOf(m, {LightType::Dir}, EnvironmentMode::None, Precision::Fp32);
  for (ProbeLanguage language : kTranslated) {
    LanguageProbe p = buildPermutationProbeIn(lib, perm, language);
    INFO(languageName(language));
    REQUIRE(validateProbe(devicesFor(language), p, "permutation", 512, 5).passed());
    const std::regex pi(R"(0\.3183098[0-9]*)");
    REQUIRE(std::regex_search(p.source, pi));
    p.source = std::regex_replace(p.source, pi, "0.3125");
    if (language == ProbeLanguage::Hlsl) REQUIRE(compileHlsl(p.source, p.program.compiled.spirv).empty());
    ValidationRecord r = validateProbe(devicesFor(language), p, "permutation", 512, 5);
    CHECK(!r.passed());
    CHECK(r.stats.failures > 0);
  }
}

TEST_CASE("validate --target runs the CLI in each language; spirv's output is unchanged",
          "[languages][cli][vulkan][gl]") {
  const std::string m = (test::sourceDir() / "materials/filament_plastic.json").string();
  const std::string args = "validate -q " + m + " --lights dir --environment none --samples 256 --json";
  const auto spirv = test::runCli(args);
  INFO(spirv.output);
  CHECK(spirv.exitCode == 0);
  CHECK(spirv.output.find("\"target\"") == std::string::npos);  // the default's records as before
  for (const char* target : {"spirv", "hlsl", "glsl450", "essl310"}) {
    const auto r = test::runCli(args + " --target " + target);
    INFO(target << ": " << r.output);
    CHECK(r.exitCode == 0);
    CHECK((r.output.find(std::string("\"target\": \"") + target + "\"") != std::string::npos) ==
          (std::string(target) != "spirv"));
  }
  CHECK(test::runCli(args + " --target msl").exitCode == 2);
}

TEST_CASE("validate --target essl310 without EGL's surfaceless platform is one line and exit 4", "[languages][cli]") {
  // libglvnd with no vendor library: no EGL implementation at all.
  const std::string m = (test::sourceDir() / "materials/filament_plastic.json").string();
  const auto r = test::runCli("validate -q " + m + " --lights dir --environment none --samples 64 --target essl310",
                              "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/egl_vendor.json");
  INFO(r.output);
  CHECK(r.exitCode == 4);
  CHECK(r.output.rfind("error: no OpenGL ES 3.1 context on EGL's surfaceless platform: ", 0) == 0);
  CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
}

TEST_CASE("llvmpipe runs ESSL mediump at 16 bits: the essl310 fp16 kernel is true half precision",
          "[languages][vulkan][gl]") {
  // Mesa's GLSL compiler lowers mediump to 16-bit floats for llvmpipe, so the essl310 form of an
  // fp16 permutation computes in half there (lavapipe ignores RelaxedPrecision: the same form's
  // SPIR-V runs at fp32). Shown on one permutation: the ESSL with every mediump written highp
  // is within the fp32 tolerance of the fp16 permutation's reference at every value (the
  // translation computes the right function), the mediump ESSL is not, and the mediump SPIR-V on
  // lavapipe is again (it runs at fp32).
  const ShaderLibrary& lib = test::shippedLibrary();
  const MaterialDesc m = test::shippedMaterial("velvet_green");
  Permutation perm =
      permutationOf(m, {LightType::Dir, LightType::Point, LightType::Spot}, EnvironmentMode::None, Precision::Fp32);
  const Tolerance fp32 = buildPermutationProbe(lib, perm).tolerance;
  perm.precision = Precision::Fp16;
  LanguageProbe es = buildPermutationProbeIn(lib, perm, ProbeLanguage::Essl310);
  REQUIRE(es.source.find("mediump") != std::string::npos);
  LanguageProbe highp = es;
  highp.source = std::regex_replace(es.source, std::regex("mediump"), "highp");
  ProbeProgram vk = buildPermutationProbe(lib, perm);
  vk.shader = emitPermutation(lib, perm, false, EmitMode::Probe, true);
  vk.compiled = compileComputeGlsl(vk.shader.glsl, vk.shader.fileName);
  vk.precision = ShaderPrecision::Fp16Mediump;
  const auto inputs = generateSamples(es.program.shader.layout, es.program.domain, 4096, 1);
  ProbeRun ref = runProbeOn(devicesFor(ProbeLanguage::Essl310), es, inputs);
  computeReference(ref, es.program, {});
  // Values outside the fp32 tolerance (with the conditioning allowance of the reference run).
  auto outside = [&](const ProbeRun& x) {
    size_t n = 0;
    for (size_t i = 0; i < x.gpu.size(); ++i)
      n += !(std::abs(x.gpu[i] - ref.reference[i]) <=
             fp32.abs + fp32.rel * std::abs(ref.reference[i]) + ref.conditioning[i]);
    return n;
  };
  const size_t mediumpOutside = outside(ref);
  const size_t highpOutside = outside(runProbeOn(devicesFor(ProbeLanguage::Essl310), highp, inputs));
  const size_t vulkanOutside = outside(runProbeOnGpu(vulkan(), vk, inputs));
  INFO("outside the fp32 tolerance: mediump ESSL " << mediumpOutside << ", highp ESSL " << highpOutside
                                                   << ", mediump SPIR-V on lavapipe " << vulkanOutside << " of "
                                                   << ref.gpu.size());
  CHECK(highpOutside == 0);
  CHECK(vulkanOutside == 0);
  CHECK(mediumpOutside > 0);
}
