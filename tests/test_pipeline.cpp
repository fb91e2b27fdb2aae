// The pipeline over the whole library: every brick and every example permutation is
// emitted, compiled, run on lavapipe and compared with its double reference. A new brick
// needs no test code here.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <unistd.h>

#include <spirv-tools/libspirv.hpp>

#include "compile/glsl_compiler.hpp"
#include "emit/emitter.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"
#include "validate/validation.hpp"

using namespace mb;

namespace {

std::vector<MaterialDesc> exampleMaterials() {
  std::vector<MaterialDesc> out;
  for (const auto& f : test::exampleMaterialFiles()) out.push_back(loadMaterialJson(f, test::shippedLibrary()));
  return out;
}

void requireNoLayerMessages(const harness::VulkanHarness& gpu) {
  auto msgs = gpu.validationMessages();
  for (const auto& m : msgs) UNSCOPED_INFO("validation layer: " << m);
  REQUIRE(msgs.empty());
}

}  // namespace

TEST_CASE("every brick of the manifest validates against its reference on lavapipe", "[pipeline][bricks][vulkan]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  REQUIRE(!lib.bricks().empty());
  for (const auto& brick : lib.bricks()) {
    ValidationRecord r = validateProbe(gpu, buildBrickProbe(lib, brick), "brick", 4096, 7);
    INFO(brick.id << ": max_abs " << r.stats.maxAbs << " max_rel " << r.stats.maxRel << " failures " << r.stats.failures
                  << " worst " << r.worstInput);
    CHECK(r.stats.nanCount == 0);
    CHECK(r.stats.infCount == 0);
    CHECK(r.stats.referenceInvalid == 0);
    CHECK(r.passed());
  }
  requireNoLayerMessages(gpu);
}

TEST_CASE("every example permutation validates", "[pipeline][materials][vulkan]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  auto materials = exampleMaterials();
  REQUIRE(materials.size() >= 3);
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  // What `validate materials/*` runs: every light type of the model together, once per
  // environment mode (issue 4: every model and every example passes, zero NaN and Inf).
  // 1024 samples keep this at ~15 s; the CLI default is 4096.
  std::vector<Permutation> perms;
  for (const auto& m : materials)
    for (const auto& p : validationPermutationsFor(m, lib)) perms.push_back(p);
  REQUIRE(perms.size() >= 3 * materials.size());
  for (const auto& perm : perms) {
    ValidationRecord r = validateProbe(gpu, buildPermutationProbe(lib, perm), "permutation", 1024, 3);
    INFO(r.key << ": max_rel " << r.stats.maxRel << " worst " << r.worstInput);
    CHECK(r.stats.nanCount == 0);
    CHECK(r.stats.infCount == 0);
    CHECK(r.passed());
  }
  requireNoLayerMessages(gpu);
}

TEST_CASE("SPIR-V of every permutation and brick probe passes spirv-val", "[pipeline][spirv]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
  auto materials = exampleMaterials();
  std::vector<EmittedShader> shaders;
  for (const auto& perm : permutationsFor(materials)) shaders.push_back(emitPermutation(lib, perm));
  for (const auto& b : lib.bricks()) shaders.push_back(emitBrickProbe(lib, b));
  for (const auto& s : shaders) {
    INFO(s.key);
    CompileOptions raw;
    raw.validate = false;  // validate here, independently of the compiler's own checks
    CompileOptions rawUnoptimized = raw;
    rawUnoptimized.optimization = OptimizationLevel::O0;
    auto unoptimized = compileComputeGlsl(s.glsl, s.fileName, rawUnoptimized);
    auto optimized = compileComputeGlsl(s.glsl, s.fileName, raw);
    CHECK(tools.Validate(unoptimized.spirv));
    CHECK(tools.Validate(optimized.spirv));
    // The performance passes must not grow the module.
    CHECK(spirvInstructionCount(optimized.spirv) <= spirvInstructionCount(unoptimized.spirv));
  }
}

TEST_CASE("two compiles of the same permutation are byte-identical", "[pipeline][determinism]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  auto materials = exampleMaterials();
  for (const auto& perm : permutationsFor(materials)) {
    EmittedShader a = emitPermutation(lib, perm), b = emitPermutation(lib, perm);
    CHECK(a.glsl == b.glsl);
    CHECK(compileComputeGlsl(a.glsl, a.fileName).spirv == compileComputeGlsl(b.glsl, b.fileName).spirv);
  }
}

TEST_CASE("the lean and legacy pipelines give the same SPIR-V and reject a module with the same message",
          "[pipeline][determinism]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  auto materials = exampleMaterials();
  CompileOptions legacy;
  legacy.pipeline = CompilePipeline::Legacy;
  for (const auto& perm : permutationsFor(materials)) {
    INFO(perm.key());
    EmittedShader s = emitPermutation(lib, perm);
    CHECK(compileComputeGlsl(s.glsl, s.fileName).spirv == compileComputeGlsl(s.glsl, s.fileName, legacy).spirv);
  }
  // An invalid module: the first OpFAdd given a 32-bit integer result type. Lean finds it
  // invalid with friendly names off and still reports the Legacy message, which names the
  // type ("%uint", "%int") as only friendly names do.
  EmittedShader s = emitPermutation(lib, permutationsFor(materials).front());
  std::vector<uint32_t> bad = compileComputeGlsl(s.glsl, s.fileName).spirv;
  constexpr uint32_t kOpTypeInt = 21, kOpFAdd = 129;
  uint32_t intType = 0;
  std::string intName;
  bool changed = false;
  for (size_t i = 5; i < bad.size() && !changed; i += bad[i] >> 16) {
    const uint32_t op = bad[i] & 0xffff;
    if (op == kOpTypeInt && !intType && bad[i + 2] == 32) {
      intType = bad[i + 1];
      intName = bad[i + 3] ? "%int" : "%uint";
    }
    if (op == kOpFAdd && intType) bad[i + 1] = intType, changed = true;
  }
  REQUIRE(changed);
  const std::string lean = spirvValidationErrors(bad, SPV_ENV_VULKAN_1_1);
  CHECK_THAT(lean, Catch::Contains("OpFAdd " + intName));
  CHECK(lean == spirvValidationErrors(bad, SPV_ENV_VULKAN_1_1, CompilePipeline::Legacy));
  CHECK(spirvValidationErrors(compileComputeGlsl(s.glsl, s.fileName).spirv, SPV_ENV_VULKAN_1_1).empty());
}

TEST_CASE("a permutation contains only the bricks it reaches", "[pipeline][emit]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  MaterialDesc m = loadMaterialJson((test::sourceDir() / "materials/ue4_metal.json").string(), lib);
  EmittedShader s = emitPermutation(lib, permutationsFor({m}).front());
  CHECK(s.glsl.find("#line 1 \"shaderlib/specular_v/v_schlick_ggx_ue4.glsl\"") != std::string::npos);
  CHECK(s.glsl.find("v_smith_ggx_correlated") == std::string::npos);
  CHECK(s.glsl.find("diffuse_disney_renormalized") == std::string::npos);
  CHECK(s.glsl.find("vec3 evaluateMaterial(") != std::string::npos);
  // One bound brick per slot, in model slot order.
  CHECK(s.bricks == std::vector<std::string>{"roughness_squared", "diffuse_lambert", "d_ggx", "v_schlick_ggx_ue4",
                                             "f_schlick_sg_ue4"});
}

TEST_CASE("a GLSL error inside a brick points at the brick's own file and line", "[pipeline][diagnostics]") {
  // Copy the library, break one line of d_ggx.glsl, and compile a probe of it.
  namespace fs = std::filesystem;
  fs::path root = fs::temp_directory_path() / ("mb_broken_lib_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::copy(test::sourceDir() / "shaderlib", root, fs::copy_options::recursive);
  std::string src = test::readFile(root / "specular_d/d_ggx.glsl");
  auto pos = src.find("float oneMinusNoH2");
  REQUIRE(pos != std::string::npos);
  int line = 1 + static_cast<int>(std::count(src.begin(), src.begin() + static_cast<long>(pos), '\n'));
  src.replace(pos, std::string("float oneMinusNoH2").size(), "float oneMinusNoH2 = undefinedSymbol; float unused");
  { std::ofstream(root / "specular_d/d_ggx.glsl", std::ios::binary) << src; }

  ShaderLibrary lib = ShaderLibrary::load(root);
  EmittedShader s = emitBrickProbe(lib, *lib.findBrick("d_ggx"));
  try {
    compileComputeGlsl(s.glsl, s.fileName);
    FAIL("compile should have failed");
  } catch (const DiagnosticError& e) {
    REQUIRE(!e.diagnostics().empty());
    const Diagnostic& d = e.diagnostics().front();
    CHECK(d.code == "E-GLSL");
    CHECK(d.where.file == "shaderlib/specular_d/d_ggx.glsl");
    CHECK(d.where.line == line);
    CHECK(d.where.column ==
          static_cast<int>(src.find("undefinedSymbol") - src.rfind('\n', src.find("undefinedSymbol"))));
    CHECK_THAT(d.message, Catch::Contains("undefinedSymbol"));
  }
  fs::remove_all(root);
}

// Issue 14, item 4: the regrouped Newton step keeps its derived tolerance (abs 5e-6 plus the
// input-conditioning allowance) over the grazing views it was once excluded from; 200,000
// samples reach the values where the step's denominator cancels (docs/validation.md).
TEST_CASE("max_noh_decima_newton holds its derived tolerance down to n.v = 1e-3", "[pipeline][stability][vulkan]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  const Brick* brick = lib.findBrick("max_noh_decima_newton");
  REQUIRE(brick != nullptr);
  CHECK(brick->geometry.NoV.lo == 1e-3);
  CHECK(brick->tolerance.abs <= 5e-6);
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  ValidationRecord r = validateProbe(gpu, buildBrickProbe(lib, *brick), "brick", 200000, 3);
  INFO("max abs " << r.stats.maxAbs << ", passed by conditioning " << r.stats.passedByConditioning);
  CHECK(r.passed());
  CHECK(r.stats.failures == 0);
  requireNoLayerMessages(gpu);
}

TEST_CASE("each stability fix is shown: the naive form fails where the shipped brick passes",
          "[pipeline][stability][vulkan]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  size_t variants = 0;
  for (const auto& brick : lib.bricks()) {
    if (brick.unstableFile.empty()) continue;
    ++variants;
    ValidationRecord stable = validateProbe(gpu, buildBrickProbe(lib, brick), "brick", 16384, 11);
    ValidationRecord naive = validateProbe(gpu, buildBrickProbe(lib, brick, true), "unstable_variant", 16384, 11);
    INFO(brick.id << ": stable max_rel " << stable.stats.maxRel << ", naive max_rel " << naive.stats.maxRel
                  << ", naive NaN " << naive.stats.nanCount << ", worst error/allowed: stable "
                  << stable.stats.worstRatio << ", naive " << naive.stats.worstRatio << " (" << brick.unstableProblem
                  << ")");
    CHECK(stable.passed());
    CHECK_FALSE(naive.passed());
    // The naive form is clearly worse: NaN/Inf where the stable form has none, or a worst
    // error/tolerance ratio at least 10x the stable form's (max_rel alone misses problems
    // that show in vector components near zero or as NaN).
    bool nonFinite = naive.stats.nanCount + naive.stats.infCount > 0;
    CHECK((nonFinite || naive.stats.worstRatio > 10 * stable.stats.worstRatio));
  }
  CHECK(variants >= 1);
  requireNoLayerMessages(gpu);
}
