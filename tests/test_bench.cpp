// matbricks bench (compiler/bench/, emit/bench_probe): the Pareto frontier, the DFG LUT
// arithmetic, the bench probe's kernels, and a tiny run through the library and the CLI.
// No timing is asserted: run times are measured by `matbricks bench`, not judged here.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "bench/ibl_bench.hpp"
#include "bench/pareto.hpp"
#include "bench/report.hpp"
#include "bench/svg_chart.hpp"
#include "emit/bench_probe.hpp"
#include "permute/permutation.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"
#include "validate/validation.hpp"

using namespace mb;
using namespace mb::bench;

namespace {

// Minimal XML well-formedness: one root <svg>, every element closed in order, quoted
// attributes, nothing after the root. Enough to catch a broken writer.
bool wellFormedSvg(const std::string& s, std::string& why) {
  std::vector<std::string> open;
  size_t i = s.find("<svg");
  if (i == std::string::npos) return why = "no <svg>", false;
  while ((i = s.find('<', i)) != std::string::npos) {
    size_t end = s.find('>', i);
    if (end == std::string::npos) return why = "unterminated tag", false;
    std::string tag = s.substr(i + 1, end - i - 1);
    if (std::count(tag.begin(), tag.end(), '"') % 2) return why = "unbalanced quotes in <" + tag + ">", false;
    if (tag.front() == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return why = "unexpected </" + tag.substr(1) + ">", false;
      open.pop_back();
      if (open.empty() && s.find('<', end) != std::string::npos) return why = "content after the root", false;
    } else if (tag.back() != '/') {
      open.push_back(tag.substr(0, tag.find_first_of(" \n")));
    }
    i = end + 1;
  }
  if (!open.empty()) return why = "<" + open.back() + "> not closed", false;
  return true;
}

void requireNoLayerMessages(const harness::VulkanHarness& gpu) {
  auto msgs = gpu.validationMessages();
  for (const auto& m : msgs) UNSCOPED_INFO("validation layer: " << m);
  REQUIRE(msgs.empty());
}

std::filesystem::path tempDir(const std::string& name) {
  auto d = std::filesystem::temp_directory_path() / ("mb_test_bench_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace

TEST_CASE("the Pareto frontier of a hand-made set", "[bench]") {
  const double nan = std::nan("");
  std::vector<ParetoPoint> pts{
      {1.0, 1e-1},  // 0: frontier
      {2.0, 1e-3},  // 1: frontier
      {3.0, 1e-2},  // 2: dominated by 1
      {0.5, 1.0},   // 3: frontier (cheapest)
      {4.0, 1e-6},  // 4: frontier (most accurate)
      {2.0, 1e-3},  // 5: equal to 1: neither dominates
      {5.0, 1e-6},  // 6: dominated by 4 (same error, costlier)
      {0.1, nan},   // 7: non-finite: never on the frontier
      {1.0, 0.5},   // 8: dominated by 0 (same cost, larger error)
      {-0.2, 2.0},  // 9: frontier (negative net cost is still a cost)
  };
  CHECK(paretoFrontier(pts) == std::vector<size_t>{9, 3, 0, 1, 5, 4});
  CHECK(paretoFrontier({}).empty());
  CHECK(paretoFrontier({{1.0, nan}}).empty());
}

TEST_CASE("binary16 rounding and bilinear DFG LUT sampling", "[bench][ibl]") {
  CHECK(roundToHalf(1.0) == 1.0);
  CHECK(roundToHalf(0.1) == 0.0999755859375);
  CHECK(roundToHalf(-0.1) == -0.0999755859375);
  CHECK(roundToHalf(1.0 + std::ldexp(1.0, -11)) == 1.0);                            // tie: to even
  CHECK(roundToHalf(1.0 + 3 * std::ldexp(1.0, -11)) == 1.0 + std::ldexp(1.0, -9));  // tie: to even
  CHECK(roundToHalf(3e-8) == std::ldexp(1.0, -24));                                 // subnormal
  CHECK(std::isinf(roundToHalf(70000.0)));

  DfgLut lut = buildDfgLut(4);
  REQUIRE(lut.x.size() == 16);
  // At texel centres the filter returns the texel; outside the first centre it clamps.
  for (uint32_t j = 0; j < 4; ++j)
    for (uint32_t i = 0; i < 4; ++i) {
      DfgSample d = sampleBilinear(lut, (i + 0.5) / 4, (j + 0.5) / 4);
      CHECK(d.x == Approx(lut.x[j * 4 + i]).margin(1e-15));
      CHECK(d.y == Approx(lut.y[j * 4 + i]).margin(1e-15));
    }
  CHECK(sampleBilinear(lut, 0.0, 0.125).y == Approx(lut.y[0]).margin(1e-15));
  CHECK(sampleBilinear(lut, 1.0, 1.0).y == Approx(lut.y[15]).margin(1e-15));
  CHECK(sampleBilinear(lut, 0.25, 0.125).y == Approx(0.5 * (lut.y[0] + lut.y[1])).margin(1e-15));
  // The split-sum terms are bounded by 1 (white furnace) and Int Gv Fc < Int Gv.
  for (size_t k = 0; k < 16; ++k) {
    CHECK(lut.y[k] <= 1.0 + 1e-9);
    CHECK(lut.x[k] < lut.y[k]);
  }
  CHECK(quantize(lut, LutFormat::Fp16).x[5] == roundToHalf(lut.x[5]));
  CHECK(lut.bytes(LutFormat::Fp16) == 4 * 4 * 2 * 2);
  CHECK(lut.bytes(LutFormat::Fp32) == 4 * 4 * 2 * 4);
}

TEST_CASE("DFG LUT error falls with resolution against the integrated split sum", "[bench][ibl]") {
  BenchOptions o;
  o.samples = 200;
  o.lutSizes = {4, 16};
  IblSection ibl;
  REQUIRE(measureDfgLuts(test::shippedLibrary(), o, ibl, nullptr));
  REQUIRE(ibl.luts.size() == 4);  // 2 sizes x {fp16, fp32}
  for (const auto& l : ibl.luts) {
    CHECK(l.error.values() == 600);  // every channel of f0
    CHECK(std::isfinite(l.error.maxScaled()));
    CHECK(l.error.meanScaled() <= l.error.maxScaled());
  }
  // Bilinear interpolation of a smooth function: 4x the resolution is markedly better.
  CHECK(ibl.luts[2].error.meanScaled() < 0.5 * ibl.luts[0].error.meanScaled());
  CHECK(ibl.luts[3].error.meanScaled() < 0.5 * ibl.luts[1].error.meanScaled());
}

TEST_CASE("bench probes evaluate the probe's function, once per iteration", "[bench][vulkan]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  auto materials = std::vector<MaterialDesc>{
      loadMaterialJson((test::sourceDir() / "materials/filament_plastic.json").string(), lib)};
  Permutation perm = permutationsFor(materials).front();
  const uint32_t iterations = 8;
  struct Case {
    ProbeProgram probe;
    EmittedShader timed, baseline;
  };
  std::vector<Case> cases;
  const Brick& ggx = *lib.findBrick("d_ggx");
  cases.push_back({buildBrickProbe(lib, ggx), emitBrickBenchProbe(lib, ggx, {iterations, false}),
                   emitBrickBenchProbe(lib, ggx, {iterations, true})});
  cases.push_back({buildPermutationProbe(lib, perm), emitPermutationBenchProbe(lib, perm, {iterations, false}),
                   emitPermutationBenchProbe(lib, perm, {iterations, true})});
  for (const Case& c : cases) {
    const ProbeLayout& layout = c.probe.shader.layout;
    INFO(c.timed.key);
    ProbeRun run = runProbe(gpu, c.probe, generateSamples(layout, c.probe.domain, 64, 5));
    auto kernelOut = [&](const EmittedShader& s) {
      auto k = gpu.createKernel(compileComputeGlsl(s.glsl, s.fileName).spirv);
      return gpu.run(*k, run.inputs, layout.inStride, layout.outStride, run.count).outputs;
    };
    std::vector<float> timed = kernelOut(c.timed), base = kernelOut(c.baseline);
    for (uint64_t i = 0; i < run.count; ++i) {
      // The inputs move by at most (iterations - 1) 2^-20 relative: the mean of the timed
      // loop is the probe's value to ~1e-5 relative (GGX D's sensitivity to alpha is <= ~4),
      // plus the problem's own sensitivity to the ulp-level direction changes that scaling
      // n, v, l before normalizing brings (the conditioning validate allows for).
      for (uint32_t k = 0; k < layout.outStride; ++k) {
        size_t at = i * layout.outStride + k;
        double probe = run.gpu[at], mean = timed[at] / iterations;
        CHECK(std::abs(mean - probe) <= 1e-3 * std::abs(probe) + 1e-6 + 2.0 * run.conditioning[at]);
      }
      // Baseline: the sum of all scaled inputs, accumulated over the iterations.
      double sum = 0, scale = 0;
      for (uint32_t k = 0; k < layout.inStride; ++k) sum += run.inputs[i * layout.inStride + k];
      for (uint32_t it = 0; it < iterations; ++it) scale += 1.0 - it * std::ldexp(1.0, -20);
      CHECK(base[i * layout.outStride] == Approx(sum * scale).epsilon(1e-5).margin(1e-4));
    }
  }
  requireNoLayerMessages(gpu);
}

TEST_CASE("a tiny bench run: finite numbers, the validator's instruction count, well-formed outputs",
          "[bench][vulkan]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  BenchOptions o;
  o.bricks = {"d_ggx", "f_schlick"};
  o.samples = 256;
  o.cost.repeats = 1;
  o.cost.records = 256;
  o.cost.iterations = 4;
  BenchReport r = runBench(lib, gpu, {}, o, nullptr);
  REQUIRE(r.groups.size() == 2);
  for (const auto& g : r.groups) {
    REQUIRE(g.items.size() == 1);
    const BenchItem& it = g.items[0];
    INFO(it.id);
    CHECK(std::isfinite(it.cost.nsPerEval));
    CHECK(it.cost.nsRaw > 0);
    CHECK(it.cost.nsBaseline > 0);
    CHECK(it.cost.evaluations == 256 * 4);
    CHECK(it.error.nonFinite() == 0);
    CHECK(it.error.truthInvalid() == 0);
    CHECK(std::isfinite(it.error.maxScaled()));
    CHECK(it.error.meanScaled() <= it.error.maxScaled());
    CHECK(it.vsReference.passed());
    CHECK(it.onFrontier);  // alone in its group
    ValidationRecord v = validateProbe(gpu, buildBrickProbe(lib, *lib.findBrick(it.id)), "brick", 16, 1);
    CHECK(it.spirvInstructions == v.spirvInstructions);
    CHECK(it.error.values() == 256 * v.stats.components / 16);

    std::string why, svg = paretoSvg(g, describeRun(r));
    CHECK(wellFormedSvg(svg, why));
    INFO(why);
    CHECK(svg.find("<polyline") != std::string::npos);
    CHECK(svg.find(it.id) != std::string::npos);
  }
  // d_ggx is exact (no ground truth): measured against its own reference; f_schlick has one.
  CHECK(r.groups[0].name == "specular_d");
  CHECK(r.groups[0].items[0].yardstick == "reference");
  CHECK(r.groups[1].items[0].yardstick == "ground_truth");
  // Schlick's approximation is far from exact Fresnel; the fp32 error of d_ggx is not.
  CHECK(r.groups[1].items[0].error.maxScaled() > 1e-3);
  CHECK(r.groups[0].items[0].error.maxScaled() < 1e-4);

  nlohmann::json j = nlohmann::json::parse(toJson(r).dump());
  CHECK(j["groups"].size() == 2);
  CHECK(j["groups"][0]["frontier"][0] == "d_ggx");
  std::string csv = toCsv(r);
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 3);
  std::string md = toMarkdown(r);
  CHECK(md.find("### `specular_d`") != std::string::npos);
  std::string doc = std::string("intro\n") + kMarkdownBegin + "\nold\n" + kMarkdownEnd + "\ntail\n";
  CHECK(spliceGenerated(doc, "new\n") ==
        std::string("intro\n") + kMarkdownBegin + "\nnew\n" + kMarkdownEnd + "\ntail\n");
  requireNoLayerMessages(gpu);
}

TEST_CASE("matbricks bench writes its outputs and rejects unknown names", "[bench][cli][vulkan]") {
  auto dir = tempDir("cli");
  auto r = test::runCli("bench --brick f_schlick --samples 64 --repeats 1 --records 256 --iterations 2 -o " +
                        (dir / "out").string() + " --csv " + (dir / "b.csv").string());
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  for (const char* f : {"bench.json", "bench.csv", "bench.md", "fresnel.svg"})
    CHECK(std::filesystem::exists(dir / "out" / f));
  CHECK(test::readFile(dir / "b.csv") == test::readFile(dir / "out" / "bench.csv"));

  auto bad = test::runCli("bench --slot specular_dd -o " + (dir / "bad").string());
  CHECK(bad.exitCode == 3);
  CHECK(bad.output.find("error[E-UNKNOWN-SLOT]") != std::string::npos);
  CHECK(bad.output.find("specular_d") != std::string::npos);  // the suggestion
  CHECK_FALSE(std::filesystem::exists(dir / "bad"));
  std::filesystem::remove_all(dir);
}
