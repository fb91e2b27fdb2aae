// The fp16 emulation (compile/fp16_emulation.hpp): half rounding, both denormal behaviours,
// division by the reciprocal and perturbed transcendentals on a small kernel; and that it
// reproduces, on lavapipe, the NaN/Inf an NVIDIA H100 gave for today's code of the bricks and
// materials fixed since (kept in tests/data/fp16_before/), while the shipped ones are clean.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

#include "compile/fp16_emulation.hpp"
#include "compile/glsl_compiler.hpp"
#include "permute/permutation.hpp"
#include "stress/stress_run.hpp"
#include "support/cli_support.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"
#include "validate/probe_program.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

// x, y -> x + y, x * y, x / y, exp(x), sqrt(x), sin(x), all in half arithmetic.
const std::string kArithmeticKernel = harness::contractKernel(
    "  float16_t x = float16_t(mbIn[2u * i]);\n"
    "  float16_t y = float16_t(mbIn[2u * i + 1u]);\n"
    "  mbOut[6u * i + 0u] = float(x + y);\n"
    "  mbOut[6u * i + 1u] = float(x * y);\n"
    "  mbOut[6u * i + 2u] = float(x / y);\n"
    "  mbOut[6u * i + 3u] = float(exp(x));\n"
    "  mbOut[6u * i + 4u] = float(sqrt(x));\n"
    "  mbOut[6u * i + 5u] = float(sin(x));\n",
    "", "#extension GL_EXT_shader_explicit_arithmetic_types_float16 : require\n");

constexpr uint32_t kOut = 6;

struct Outputs {
  std::vector<float> flush, keep;
};

Outputs runArithmetic(harness::VulkanHarness& gpu, const std::vector<float>& xy) {
  CompileOptions options;
  options.optimization = OptimizationLevel::O0;
  std::vector<uint32_t> half = compileComputeGlsl(kArithmeticKernel, "fp16_arithmetic.comp", options).spirv;
  Outputs o;
  for (Denormals d : {Denormals::Flush, Denormals::Keep}) {
    auto spirv = emulateWorstCaseFp16(half, "fp16_arithmetic.comp", d);
    auto r = gpu.run(*gpu.kernelFor(spirv), xy, 2, kOut, xy.size() / 2);
    (d == Denormals::Flush ? o.flush : o.keep) = r.outputs;
  }
  return o;
}

double halfUlp(double x) { return std::ldexp(1.0, std::max(std::ilogb(std::abs(x)), -14) - 10); }

// A copy of the shipped library with today's (pre-fix) files of tests/data/fp16_before laid
// over it.
const ShaderLibrary& libraryBeforeFixes() {
  static ShaderLibrary lib = [] {
    fs::path root = test::freshTempDir("fp16", "before") / "shaderlib";
    fs::copy(test::sourceDir() / "shaderlib", root, fs::copy_options::recursive);
    fs::copy(test::sourceDir() / "tests/data/fp16_before", root,
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    return ShaderLibrary::load(root);
  }();
  return lib;
}

uint64_t nonFinite(const StressResult& r) { return r.inDomain.nanCount + r.inDomain.infCount; }

}  // namespace

TEST_CASE("the fp16 emulation rounds, flushes or keeps denormals, and divides by the reciprocal",
          "[fp16][emulation][vulkan]") {
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  const std::vector<float> xy = {
      1.0f,    0x1p-11f,  // 1 + 2^-11: a tie, rounds to even (1) in half, not in fp32
      300.0f,  300.0f,    // 90000 overflows half: Inf
      0x1p-7f, 0x1p-8f,   // 2^-15: a denormal product
      1.0f,    32768.0f,  // 1/32768: |y| > 2^14, the reciprocal is a denormal
      0.0f,    0x1p-16f,  // a denormal divisor: 0 * (1/y) with 1/y = Inf
      1.0f,    3.0f,      // inside the range: within 2.5 ULP of 1/3
  };
  Outputs o = runArithmetic(gpu, xy);
  auto at = [](const std::vector<float>& v, int record, int k) { return v[record * kOut + k]; };
  for (const auto* v : {&o.flush, &o.keep}) {
    CHECK(at(*v, 0, 0) == 1.0f);
    CHECK(std::isinf(at(*v, 1, 1)));
    CHECK(std::isnan(at(*v, 4, 2)));
    CHECK(std::abs(at(*v, 5, 2) - 1.0 / 3.0) <= 2.5 * halfUlp(1.0 / 3.0));
  }
  CHECK(at(o.flush, 2, 1) == 0.0f);
  CHECK(at(o.keep, 2, 1) == 0x1p-15f);
  CHECK(at(o.flush, 3, 2) == 0.0f);
  CHECK(at(o.keep, 3, 2) == 0x1p-15f);
  CHECK(gpu.validationMessages().empty());
}

TEST_CASE("the fp16 emulation moves exp and sin to the edges of their spec bounds, both ways",
          "[fp16][emulation][vulkan]") {
  // Vulkan spec, "Precision and Operation of SPIR-V Instructions", half precision: exp within
  // 1 + 2|x| ULP, sin within 2^-7 absolute on [-pi, pi]; sqrt inherited from 1/inversesqrt
  // (2 ULP, then a reciprocal and its rounding: 2 + 1 + 1/2 ULP at most).
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  std::vector<float> xy;
  for (int k = 0; k < 256; ++k) xy.insert(xy.end(), {static_cast<float>(-3.0 + 6.0 * k / 255.0), 0.0f});
  Outputs o = runArithmetic(gpu, xy);
  int expUp = 0, expDown = 0, sinUp = 0, sinDown = 0;
  for (int k = 0; k < 256; ++k) {
    const double x = o.flush[k * kOut + 0];  // x + 0: the input as a half
    const double e = o.flush[k * kOut + 3], s = o.flush[k * kOut + 5];
    INFO("x = " << x << " exp " << e << " sin " << s);
    CHECK(std::abs(e - std::exp(x)) <= (1 + 2 * std::abs(x)) * halfUlp(std::exp(x)) + 1e-12);
    CHECK(std::abs(s - std::sin(x)) <= 0x1p-7 + 1e-12);
    (e > std::exp(x) ? expUp : expDown) += 1;
    (s > std::sin(x) ? sinUp : sinDown) += 1;
    // sqrt = 1 / inversesqrt: 2 ULP of inversesqrt (relative <= 2 * 2^-10), the rounded
    // reciprocal (2^-11) and the final rounding (2^-11).
    if (x > 0.1) CHECK(std::abs(o.flush[k * kOut + 4] - std::sqrt(x)) <= 3 * 0x1p-10 * std::sqrt(x));
    // Perturbed to near the edge (2^-7 less the rounding slack and the rounding), not left
    // correctly rounded.
    CHECK(std::abs(s - std::sin(x)) >= 0x1p-7 - 0x1p-10);
  }
  CHECK(expUp > 64);
  CHECK(expDown > 64);
  CHECK(sinUp > 64);
  CHECK(sinDown > 64);
}

TEST_CASE("the emulated kernel needs no shaderFloat16 and counts what it rewrote", "[fp16][emulation]") {
  // The frozen d_beckmann of tests/data/fp16_before: three divisions that do not change as the
  // shipped brick does.
  const ShaderLibrary& lib = libraryBeforeFixes();
  EmittedShader s = emitBrickProbe(lib, *lib.findBrick("d_beckmann"), false, ShaderPrecision::Fp16);
  CompileOptions options;
  options.optimization = OptimizationLevel::O0;
  std::vector<uint32_t> half = compileComputeGlsl(s.glsl, s.fileName, options).spirv;
  Fp16EmulationStats stats;
  std::vector<uint32_t> out = emulateWorstCaseFp16(half, s.fileName, Denormals::Flush, stats);
  CHECK(stats.rounded > 20);
  CHECK(stats.divisions >= 3);
  CHECK(stats.expanded >= 4);   // normalize, dot, cross, length...
  CHECK(stats.perturbed >= 2);  // exp, inversesqrt
  auto declaresCapability = [](const std::vector<uint32_t>& m, uint32_t cap) {
    for (size_t i = 5; i < m.size() && (m[i] >> 16);) {
      if ((m[i] & 0xffffu) == 17u && m[i + 1] == cap) return true;  // OpCapability
      i += m[i] >> 16;
    }
    return false;
  };
  const uint32_t float16Capability = 9;
  CHECK(declaresCapability(half, float16Capability));
  CHECK_FALSE(declaresCapability(out, float16Capability));
}

TEST_CASE("the fp16 emulation reproduces the NaN/Inf of today's bricks that a real GPU found",
          "[fp16][emulation][stress][vulkan]") {
  // Found with `stress --all-bricks --precision fp16` on an NVIDIA H100, all 0 on lavapipe's
  // own half arithmetic. tests/data/fp16_before holds these bricks as they were; the shipped
  // ones are fixed and must stay clean under the same emulation.
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  for (const char* id : {"d_ashikhmin", "d_beckmann", "d_beckmann_aniso", "v_smith_ggx_correlated_fast",
                         "v_smith_ggx_correlated_aniso", "horizon_wrap_accurate"}) {
    INFO(id);
    const ShaderLibrary& before = libraryBeforeFixes();
    StressResult old = stressProbe(gpu, buildBrickProbe(before, *before.findBrick(id), false, ShaderPrecision::Fp16),
                                   "brick", id, {256, 1});
    CHECK(nonFinite(old) > 0);
    const ShaderLibrary& lib = test::shippedLibrary();
    StressResult fixed =
        stressProbe(gpu, buildBrickProbe(lib, *lib.findBrick(id), false, ShaderPrecision::Fp16), "brick", id, {256, 1});
    CHECK(nonFinite(fixed) == 0);
  }
  CHECK(gpu.validationMessages().empty());
}

TEST_CASE("the emulation gives NaN at the H100's worst d_beckmann input, today's code only",
          "[fp16][emulation][vulkan]") {
  // n = (0,0,1), v = (0.9999995, 0, 0.001), l = (1,0,0), alpha = 0.007921: in half n.h^2 is a
  // denormal, the exponent's denominator underflows and the divisions by n.h^2 overflow the
  // reciprocal: 0 * Inf on the H100 (reference 0).
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  const std::vector<float> record = {0, 0, 1, 0.999999523f, 0, 0.00100000005f, 1, 0, 0, 0.00792100001f};
  const ShaderLibrary& before = libraryBeforeFixes();
  ProbeRun old =
      runProbe(gpu, buildBrickProbe(before, *before.findBrick("d_beckmann"), false, ShaderPrecision::Fp16), record);
  CHECK(std::isnan(old.gpu[0]));
  CHECK(old.reference[0] == 0.0);
  const ShaderLibrary& lib = test::shippedLibrary();
  ProbeRun fixed =
      runProbe(gpu, buildBrickProbe(lib, *lib.findBrick("d_beckmann"), false, ShaderPrecision::Fp16), record);
  CHECK(fixed.gpu[0] == 0.0f);
  // The driver's own half arithmetic (lavapipe) does not show it: the emulation does.
  setFp16Mode(Fp16Mode::Driver);
  ProbeRun driver =
      runProbe(gpu, buildBrickProbe(before, *before.findBrick("d_beckmann"), false, ShaderPrecision::Fp16), record);
  setFp16Mode(Fp16Mode::Emulated);
  CHECK(std::isfinite(driver.gpu[0]));
}

namespace {

// Stress of a material's fp16 permutation with these lights, on `lib`.
StressResult stressMaterial(harness::VulkanHarness& gpu, const ShaderLibrary& lib, const std::string& name,
                            const std::vector<std::string>& lights) {
  MaterialDesc m = loadMaterialJson(test::materialPath(name + ".json"), lib);
  Permutation perm;
  perm.material = &m;
  perm.lights = parseLightTypes(lights);
  perm.precision = Precision::Fp16;
  return stressProbe(gpu, buildPermutationProbe(lib, perm, true), "permutation", name, {256, 1});
}

}  // namespace

TEST_CASE("the fp16 emulation reproduces brushed_metal's Inf of today's skeleton; the shipped one is clean",
          "[fp16][emulation][stress][vulkan]") {
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  CHECK(nonFinite(stressMaterial(gpu, libraryBeforeFixes(), "brushed_metal", {"dir"})) > 0);
  CHECK(nonFinite(stressMaterial(gpu, test::shippedLibrary(), "brushed_metal", {"dir"})) == 0);
  CHECK(gpu.validationMessages().empty());
}

// Opt-in with the whole-library stress (CTest label "stress"): the five-light permutation's
// emulated kernel takes lavapipe about a minute to compile on 2 cores.
TEST_CASE("the fp16 emulation reproduces filament_plastic's NaN with all five lights; the shipped one is clean",
          "[.stress-library][fp16][emulation][stress]") {
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  const std::vector<std::string> lights = {"dir", "point", "spot", "sphere", "tube"};
  CHECK(nonFinite(stressMaterial(gpu, libraryBeforeFixes(), "filament_plastic", lights)) > 0);
  CHECK(nonFinite(stressMaterial(gpu, test::shippedLibrary(), "filament_plastic", lights)) == 0);
  CHECK(gpu.validationMessages().empty());
}
