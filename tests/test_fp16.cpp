// The fp16 precision axis: the half rewriter on its own, fp16 probes on lavapipe (true half
// arithmetic, shaderFloat16 enabled, validation layer silent), fp16 permutations.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "emit/fp16_rewrite.hpp"
#include "permute/permutation.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"
#include "validate/probe_program.hpp"

using namespace mb;

namespace {

void requireNoLayerMessages(const harness::VulkanHarness& gpu) {
  auto msgs = gpu.validationMessages();
  for (const auto& m : msgs) UNSCOPED_INFO("validation layer: " << m);
  REQUIRE(msgs.empty());
}

// One input column, `count` values spread over [lo, hi].
std::vector<float> ramp(double lo, double hi, int count) {
  std::vector<float> v;
  for (int i = 0; i < count; ++i) v.push_back(static_cast<float>(lo + (hi - lo) * i / (count - 1)));
  return v;
}

}  // namespace

TEST_CASE("the fp16 rewriter maps types and suffixes float literals", "[fp16][emit]") {
  CHECK(rewriteToFp16("float x = 1.0;") == "float16_t x = 1.0hf;");
  CHECK(rewriteToFp16("vec3 a = vec3(0.5, .25, 2.);") == "f16vec3 a = f16vec3(0.5hf, .25hf, 2.hf);");
  CHECK(rewriteToFp16("vec2 b; vec4 c; mat3 m; mat2x3 k;") == "f16vec2 b; f16vec4 c; f16mat3 m; f16mat2x3 k;");
  CHECK(rewriteToFp16("y = 1e-4 + 2.5e+3 + 3E2;") == "y = 1e-4hf + 2.5e+3hf + 3E2hf;");
  CHECK(rewriteToFp16("y = 2.5f * 1.0F;") == "y = 2.5hf * 1.0hf;");
}

TEST_CASE("the fp16 rewriter leaves integers, doubles, half literals and other identifiers alone", "[fp16][emit]") {
  CHECK(rewriteToFp16("int i = 3; uint u = 7u; uint h = 0x1Fu;") == "int i = 3; uint u = 7u; uint h = 0x1Fu;");
  CHECK(rewriteToFp16("double d = 1.0lf; float16_t h = 1.0hf;") == "double d = 1.0lf; float16_t h = 1.0hf;");
  CHECK(rewriteToFp16("uint b = floatBitsToUint(x);") == "uint b = floatBitsToUint(x);");
  CHECK(rewriteToFp16("my_vec3 = vec3x + floaty + f16vec3(h);") == "my_vec3 = vec3x + floaty + f16vec3(h);");
  CHECK(rewriteToFp16("a[2] = v.x;") == "a[2] = v.x;");
}

TEST_CASE("the fp16 rewriter skips comments and directives but rewrites #define bodies", "[fp16][emit]") {
  const std::string src =
      "#version 450\n"
      "#line 12 \"shaderlib/specular_d/d_ggx.glsl\"\n"
      "// float 1.0 in a comment\n"
      "/* vec3 2.0\n   still a comment 3.0 */ float a = 4.0; // 5.0\n"
      "#define MB_PI 3.14159265358979323846\n"
      "#ifdef MB_FP16\n"
      "#endif\n";
  const std::string out = rewriteToFp16(src);
  CHECK(out ==
        "#version 450\n"
        "#line 12 \"shaderlib/specular_d/d_ggx.glsl\"\n"
        "// float 1.0 in a comment\n"
        "/* vec3 2.0\n   still a comment 3.0 */ float16_t a = 4.0hf; // 5.0\n"
        "#define MB_PI 3.14159265358979323846hf\n"
        "#ifdef MB_FP16\n"
        "#endif\n");
  // Line structure is kept, so #line directives stay right.
  CHECK(std::count(out.begin(), out.end(), '\n') == std::count(src.begin(), src.end(), '\n'));
}

TEST_CASE("an fp16 brick probe enables half arithmetic and defines MB_FP16", "[fp16][emit]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  EmittedShader s = emitBrickProbe(lib, *lib.findBrick("d_ggx"), false, ShaderPrecision::Fp16);
  CHECK(s.key == "brick.d_ggx.fp16");
  CHECK(s.glsl.find("#extension GL_EXT_shader_explicit_arithmetic_types_float16 : require") != std::string::npos);
  CHECK(s.glsl.find("#define MB_FP16 1") != std::string::npos);
  CHECK(s.glsl.find("float16_t mb_d_ggx(Geometry g, float16_t alpha)") != std::string::npos);
  // Buffers stay fp32; values convert at the boundary.
  CHECK(s.glsl.find("readonly buffer MbIn { float mbIn[]; }") != std::string::npos);
  CHECK(s.glsl.find("mbOut[o + 0u] = float(r);") != std::string::npos);
  EmittedShader fp32 = emitBrickProbe(lib, *lib.findBrick("d_ggx"));
  CHECK(fp32.glsl.find("#define MB_FP16") == std::string::npos);  // guards are in the sources, not taken
  CHECK(fp32.glsl.find("float16_t") == std::string::npos);
}

TEST_CASE("lavapipe offers shaderFloat16 and the harness enables it", "[fp16][harness][vulkan]") {
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  REQUIRE(gpu.isLavapipe());
  CHECK(gpu.supportsShaderFloat16());
  requireNoLayerMessages(gpu);
}

TEST_CASE("an fp16 probe runs on lavapipe and stays within its half-precision bound of fp32",
          "[fp16][harness][vulkan]") {
  // roughness_squared is one product r * r. In half precision the input is rounded (relative
  // error u = 2^-11), the square doubles that, and the product rounds once more: 3u relative,
  // for results above fp16's smallest normal 2^-14 (inputs >= 0.01 keep r^2 >= 1e-4 there).
  const ShaderLibrary& lib = test::shippedLibrary();
  const Brick& brick = *lib.findBrick("roughness_squared");
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  ProbeProgram p16 = buildBrickProbe(lib, brick, false, ShaderPrecision::Fp16);
  ProbeProgram p32 = buildBrickProbe(lib, brick);
  std::vector<float> inputs = ramp(0.01, 1.0, 1000);
  ProbeRun r16 = runProbe(gpu, p16, inputs);
  ProbeRun r32 = runProbe(gpu, p32, inputs);
  const double u = std::ldexp(1.0, -11);
  size_t differ = 0;
  for (size_t i = 0; i < inputs.size(); ++i) {
    double ref = r16.reference[i];
    INFO("r = " << inputs[i] << " fp16 = " << r16.gpu[i] << " fp32 = " << r32.gpu[i] << " ref = " << ref);
    REQUIRE(std::isfinite(r16.gpu[i]));
    CHECK(std::abs(r16.gpu[i] - ref) <= 3 * u * ref);
    CHECK(std::abs(r16.gpu[i] - r32.gpu[i]) <= 3 * u * ref + 2 * std::ldexp(1.0, -24) * ref);
    differ += r16.gpu[i] != r32.gpu[i];
  }
  // Real half arithmetic: most results are not the fp32 ones (an fp32 path would give 0).
  CHECK(differ > inputs.size() / 2);
  requireNoLayerMessages(gpu);
}

TEST_CASE("fp16 probes of geometry bricks run without NaN or Inf in the fp16 domain", "[fp16][harness][vulkan]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  for (const char* id : {"d_ggx", "v_smith_ggx_correlated", "f_schlick", "diffuse_lambert"}) {
    INFO(id);
    ProbeProgram p = buildBrickProbe(lib, *lib.findBrick(id), false, ShaderPrecision::Fp16);
    bool alphaAtFp16Floor =
        p.domain.ranges.count("alpha") == 0 || p.domain.ranges.at("alpha").lo >= 0.089 * 0.089 - 1e-12;
    CHECK(alphaAtFp16Floor);
    ProbeRun run = runProbe(gpu, p, generateSamples(p.shader.layout, p.domain, 2048, 7));
    ErrorStats s = compare(run, p);
    CHECK(s.nanCount == 0);
    CHECK(s.infCount == 0);
    CHECK(s.referenceInvalid == 0);
    CHECK(s.passed());
  }
  requireNoLayerMessages(gpu);
}

TEST_CASE("fp16 material permutations use the fp16 roughness clamp", "[fp16][emit]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  MaterialDesc m = loadMaterialJson((test::sourceDir() / "materials/filament_plastic.json").string(), lib);
  REQUIRE(m.bricks.at("roughness") == "roughness_clamped");
  Permutation perm;
  perm.material = &m;
  perm.precision = Precision::Fp16;
  EmittedShader s = emitPermutation(lib, perm);
  CHECK(s.key == "filament_plastic.standard.dir.none.fp16");
  CHECK(std::count(s.bricks.begin(), s.bricks.end(), "roughness_clamped_fp16") == 1);
  CHECK(std::count(s.bricks.begin(), s.bricks.end(), "roughness_clamped") == 0);
  CHECK(s.glsl.find("f16vec3 evaluateMaterial(f16vec3 n") != std::string::npos);
  CHECK(!parsePrecision("fp8"));  // an unknown precision is refused where it is read
}

TEST_CASE("an fp16 permutation runs on lavapipe without NaN/Inf where its exact value is in range",
          "[fp16][harness][vulkan]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  MaterialDesc m = loadMaterialJson((test::sourceDir() / "materials/filament_plastic.json").string(), lib);
  Permutation perm;
  perm.material = &m;
  perm.precision = Precision::Fp16;
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  ProbeProgram p = buildPermutationProbe(lib, perm);
  CHECK(p.domain.ranges.at("roughness").lo == Approx(0.089));
  ProbeRun run = runProbe(gpu, p, generateSamples(p.shader.layout, p.domain, 2048, 3));
  // Under the fp16 emulation (the least precise conforming device): the skeleton multiplies
  // the cosine into V before D and clamps each light's radiance to 65504 (saturateMediump),
  // so no value is NaN, nor Inf where the exact value fits in half (docs/stress.md).
  size_t nan = 0, infInRange = 0, overflow = 0;
  for (size_t i = 0; i < run.gpu.size(); ++i) {
    nan += std::isnan(run.gpu[i]);
    bool inf = std::isinf(run.gpu[i]);
    infInRange += inf && std::abs(run.reference[i]) <= 65504.0;
    overflow += inf && std::abs(run.reference[i]) > 65504.0;
  }
  INFO("fp16 filament_plastic over 2048 samples: NaN " << nan << ", Inf with the exact value in range " << infInRange
                                                       << ", beyond the half range " << overflow);
  CHECK(run.count == 2048);
  CHECK(p.fp16Mode == Fp16Mode::Emulated);
  CHECK(nan == 0);
  CHECK(infInRange == 0);
  requireNoLayerMessages(gpu);
}

TEST_CASE("the mediump (ESSL) form of fp16 permutations computes the fp32 function on lavapipe, but for its caps",
          "[fp16][harness][vulkan]") {
  // Lavapipe ignores RelaxedPrecision, so the mediump form runs at fp32 there. Against the
  // fp16 permutation's own reference (its bricks, the fp16 roughness floor, the fp16 domain)
  // each value must be within the fp32 tolerance, except where one of MB_FP16's half-range
  // guards caps it (Filament's saturateMediump, min(x, 65504), in V_Kelemen, the coat and
  // sheen lobes; the sheen's cut below n.l = 1e-3): those only ever lower a value, and only
  // at degenerate geometry. This checks what the form changes besides the driver's choice of
  // precision: the guards, the highp buffer loads, the record layout.
  const ShaderLibrary& lib = test::shippedLibrary();
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  for (const char* name : {"filament_plastic", "clearcoat_metal", "satin_sheen", "velvet_green"}) {
    MaterialDesc m = test::shippedMaterial(name);
    Permutation perm;
    perm.material = &m;
    perm.lights = {LightType::Dir, LightType::Point, LightType::Spot};
    perm.environment = EnvironmentMode::IblLut;
    perm.precision = Precision::Fp32;
    const Tolerance tol = buildPermutationProbe(lib, perm).tolerance;
    perm.precision = Precision::Fp16;
    ProbeProgram p = buildPermutationProbe(lib, perm);
    p.shader = emitPermutation(lib, perm, false, EmitMode::Probe, true);
    p.compiled = compileComputeGlsl(p.shader.glsl, p.shader.fileName);
    p.precision = ShaderPrecision::Fp16Mediump;
    ProbeRun run = runProbe(gpu, p, generateSamples(p.shader.layout, p.domain, 4096, 5));
    size_t capped = 0, wrong = 0;
    for (size_t i = 0; i < run.gpu.size(); ++i) {
      const double g = run.gpu[i], r = run.reference[i];
      REQUIRE(std::isfinite(g));
      if (std::abs(g - r) <= tol.abs + tol.rel * std::abs(r) + run.conditioning[i]) continue;
      (g < r ? capped : wrong) += 1;
    }
    INFO(name << ": " << capped << " capped and " << wrong << " wrong of " << run.gpu.size() << " values");
    CHECK(wrong == 0);
    CHECK(capped * 200 < run.gpu.size());  // under 0.5 %
  }
  requireNoLayerMessages(gpu);
}

TEST_CASE("validate --precision fp16 runs a brick and exits 0", "[fp16][cli][vulkan]") {
  auto r = test::runCli("validate --brick d_ggx --precision fp16 --samples 512 --json");
  INFO(r.output);
  CHECK(r.exitCode == 0);
  CHECK(r.output.find("\"brick.d_ggx.fp16\"") != std::string::npos);
  auto bad = test::runCli("validate --brick d_ggx --precision fp8");
  CHECK(bad.exitCode == 2);
  // The driver's own half arithmetic, to compare (lavapipe offers shaderFloat16).
  auto driver = test::runCli("validate --brick d_ggx --precision fp16 --fp16 driver --samples 512 --json");
  CHECK(driver.exitCode == 0);
  CHECK(test::runCli("validate --brick d_ggx --precision fp16 --fp16 fast").exitCode == 2);
}
