// matbricks bench (compiler/bench_engine/, emit/bench_probe): the Pareto frontier, the DFG LUT
// arithmetic, the bench probe's kernels, and a tiny run through the library and the CLI.
// No timing is asserted: run times are measured by `matbricks bench`, not judged here.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "bench_engine/cost_format.hpp"
#include "bench_engine/cost_interval.hpp"
#include "bench_engine/ibl_bench.hpp"
#include "bench_engine/light_methods.hpp"
#include "bench_engine/pareto.hpp"
#include "bench_engine/report.hpp"
#include "bench_engine/static_cost.hpp"
#include "bench_engine/svg_chart.hpp"
#include "emit/bench_probe.hpp"
#include "core/value_type.hpp"
#include "lut/dfg_lut.hpp"
#include "permute/permutation.hpp"
#include "support/cli_support.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"
#include "validate/validation.hpp"

using namespace mb;
using namespace mb::bench;
using mb::lut::buildDfgLut;
using mb::lut::DfgLut;
using mb::lut::DfgSample;
using mb::lut::LutFormat;
using mb::lut::quantize;
using mb::lut::roundToHalf;
using mb::lut::sampleBilinear;

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

TEST_CASE("the frontier counts a cost as lower only where the intervals are disjoint", "[bench]") {
  std::vector<ParetoPoint> pts{
      {1.0, 1e-2, 0.9, 1.1},     // 0: nominally cheapest resolved, but within the noise of 1: a tie with 1
      {1.05, 1e-4, 0.95, 1.15},  // 1: frontier (wins the tie: more accurate)
      {2.0, 1e-6, 1.9, 2.1},     // 2: frontier (significantly costlier than 1, more accurate)
      {3.0, 1e-3, 2.9, 3.1},     // 3: dominated by 1 outright: not a tie
      {0.1, 1e-1, 0.0, 0.5},     // 4: below resolution, bound 0.5 < 0.95: significantly cheaper, frontier
      {2.05, 1e-6, 1.95, 2.2},   // 5: equal error to 2, overlapping cost: neither dominates, both frontier
  };
  FrontierMarks m = paretoFrontierWithTies(pts);
  CHECK(m.frontier == std::vector<size_t>{4, 1, 2, 5});
  REQUIRE(m.tiedWith.size() == pts.size());
  CHECK(m.tiedWith[0] == std::optional<size_t>{1});
  for (size_t i : {1, 2, 3, 4, 5}) CHECK_FALSE(m.tiedWith[i]);
  // Disjoint intervals restore the classic rule: 0 is then significantly cheaper than 1.
  pts[0].costHigh = 0.94;
  m = paretoFrontierWithTies(pts);
  CHECK(m.frontier == std::vector<size_t>{4, 0, 1, 2, 5});
  CHECK_FALSE(m.tiedWith[0]);
  // Everything within one interval: only the most accurate point remains, the others tie with it.
  std::vector<ParetoPoint> noise{{0.3, 1e-1, 0.0, 1.0}, {0.5, 1e-2, 0.0, 1.0}, {0.7, 1e-3, 0.0, 1.0}};
  m = paretoFrontierWithTies(noise);
  CHECK(m.frontier == std::vector<size_t>{2});
  CHECK(m.tiedWith[0] == std::optional<size_t>{2});
  CHECK(m.tiedWith[1] == std::optional<size_t>{2});
}

TEST_CASE("the median's order-statistic interval and the below-resolution rule", "[bench]") {
  // Coverage of [x(k), x(n+1-k)]: 1 - 2 P(Binomial(n, 1/2) <= k - 1).
  CHECK(orderStatisticCoverage(9, 2) == Approx(1 - 2 * 10.0 / 512));
  CHECK(orderStatisticCoverage(6, 1) == Approx(1 - 2 / 64.0));
  CHECK(orderStatisticCoverage(1, 1) == 0.0);
  // n = 9: k = 2 (96.1 %); k = 3 would be 82 %.
  MedianInterval m = medianInterval({9, 1, 8, 2, 7, 3, 6, 4, 5});
  CHECK(m.median == 5);
  CHECK(m.low == 2);
  CHECK(m.high == 8);
  CHECK(m.confidence == Approx(0.9609375));
  // n = 20: P(B <= 5) = 21700 / 2^20, so k = 6: [x(6), x(15)] at 95.9 %.
  std::vector<double> twenty;
  for (int i = 20; i >= 1; --i) twenty.push_back(i);
  m = medianInterval(twenty);
  CHECK(m.low == 6);
  CHECK(m.high == 15);
  CHECK(m.confidence == Approx(1 - 2 * 21700.0 / 1048576));
  // Too few repeats for 95 %: [min, max] at its own, lower coverage; never resolved.
  m = medianInterval({3, 1, 2, 5, 4});
  CHECK(m.low == 1);
  CHECK(m.high == 5);
  CHECK(m.confidence == Approx(0.9375));
  CHECK_FALSE(separatedFromEmptyLoop(m, 0.001));
  CHECK(medianInterval({}).samples == 0);

  // Synthetic paired differences (ms per dispatch), timer resolution 0.002 ms.
  const double resolution = 0.002;
  CHECK(separatedFromEmptyLoop(medianInterval({1.0, 1.1, 0.9, 1.05, 0.95, 1.02, 0.98, 1.01, 0.99}), resolution));
  // Straddling zero: the kernel is not separated from the empty loop.
  CHECK_FALSE(separatedFromEmptyLoop(medianInterval({0.3, -0.2, 0.1, -0.4, 0.2, 0.05, -0.1, 0.15, -0.05}), resolution));
  // Positive but within the timer's resolution.
  CHECK_FALSE(separatedFromEmptyLoop(
      medianInterval({0.001, 0.0015, 0.0012, 0.0011, 0.0013, 0.0014, 0.001, 0.0012, 0.0011}), resolution));
  // One outlier does not move an order-statistic interval (it would a t-interval).
  MedianInterval outlier = medianInterval({1.0, 1.1, 0.9, 1.05, 0.95, 1.02, 0.98, 1.01, 500.0});
  CHECK(outlier.high <= 1.1);
  CHECK(separatedFromEmptyLoop(outlier, resolution));
  CHECK(significantlyCheaper({1, 2}, {2.5, 3}));
  CHECK_FALSE(significantlyCheaper({1, 2}, {2, 3}));
  CHECK_FALSE(significantlyCheaper({2.5, 3}, {1, 2}));
}

TEST_CASE("costs print as 3 significant digits in a fitting unit, never 0 or negative", "[bench]") {
  CHECK(formatDuration(0.000712) == "712 fs");
  CHECK(formatDuration(0.0123) == "12.3 ps");
  CHECK(formatDuration(0.9996) == "1.00 ns");  // rounds into the next unit, not "1000 ps"
  CHECK(formatDuration(0.99949) == "999 ps");
  CHECK(formatDuration(1.0) == "1.00 ns");
  CHECK(formatDuration(42.0) == "42.0 ns");
  CHECK(formatDuration(1234.5) == "1.23 µs");
  CHECK(formatDuration(2.5e6) == "2.50 ms");
  CHECK(formatDuration(3e9) == "3.00 s");
  CHECK(formatDuration(1.5e13) == "15000 s");
  CHECK(formatDuration(1e-9) == "1.00e-3 fs");
  for (double bad : {0.0, -0.0, -1e-12, -0.01, -5.0, std::nan(""), double(INFINITY), -double(INFINITY)})
    CHECK(formatDuration(bad) == "n/a");
  // A sweep over 24 decades: a positive number with exactly 3 significant digits and a unit.
  for (double v = 1.7e-6; v < 1e11; v *= 1.37) {
    std::string t = formatDuration(v);
    INFO(v << " -> " << t);
    CHECK(t.front() != '-');
    CHECK(t.rfind("0.0", 0) != 0);
    CHECK(std::stod(t) > 0);
    size_t significant = 0;
    bool leading = true;
    for (char c : t.substr(0, t.find(' '))) {
      if (c == 'e') break;
      if (std::isdigit(static_cast<unsigned char>(c)) && !(leading && c == '0')) ++significant, leading = false;
    }
    CHECK(significant == 3);
  }
  // A measurement that is not resolved prints no value, only the (positive) bound it is below,
  // however negative or zero its raw median and interval.
  CostMeasurement c;
  c.nsPerEval = -0.01;
  c.nsPerEvalLow = -0.6;
  c.nsPerEvalHigh = 0.0;
  c.nsResolution = 0.000125;
  CHECK(formatCost(c) == "below resolution");
  CHECK(formatCostWithInterval(c) == "below resolution (< 125 fs)");
  c.nsPerEvalHigh = 0.0234;
  CHECK(formatCostWithInterval(c) == "below resolution (< 23.4 ps)");
  c.resolved = true;
  c.nsPerEval = 1.234;
  c.nsPerEvalLow = 1.2;
  c.nsPerEvalHigh = 1.27;
  CHECK(formatCost(c) == "1.23 ns");
  CHECK(formatCostWithInterval(c) == "1.23 ns (1.20 ns to 1.27 ns)");
}

TEST_CASE("static cost: deterministic, per evaluation, and ordered as the operations are", "[bench]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  auto kernels = [&](const std::string& id, uint32_t iterations) {
    const Brick& b = *lib.findBrick(id);
    EmittedShader t = emitBrickBenchProbe(lib, b, {iterations, false}),
                  e = emitBrickBenchProbe(lib, b, {iterations, true});
    return std::pair{compileComputeGlsl(t.glsl, t.fileName).spirv, compileComputeGlsl(e.glsl, e.fileName).spirv};
  };
  auto perEval = [&](const std::string& id, uint32_t iterations) {
    return staticCostPerEvaluation(kernels(id, iterations).first);
  };
  // The loop's trip count is read from the kernel: the same cost per evaluation at 4 and 8
  // iterations, and twice the loop's share of the whole kernel at 8.
  const double ggx4 = perEval("d_ggx", 4), ggx8 = perEval("d_ggx", 8);
  CHECK(ggx4 == ggx8);
  CHECK(perEval("d_ggx", 4) == ggx4);  // deterministic
  StaticCost s2 = staticCost(kernels("d_ggx", 2).first), s4 = staticCost(kernels("d_ggx", 4).first),
             s8 = staticCost(kernels("d_ggx", 8).first);
  CHECK(s4.loops == 1);
  CHECK(s4.loopsWithUnknownTripCount == 0);
  CHECK(s8.fmaSlots - s4.fmaSlots == Approx(2 * (s4.fmaSlots - s2.fmaSlots)));  // linear in the trip count
  // Per evaluation is one iteration of the loop less its counter (an integer add and
  // compare, weight 2 each: op_weights.cpp), which is the whole kernel's per-iteration growth.
  CHECK(ggx4 == Approx((s4.fmaSlots - s2.fmaSlots) / 2 - 4));
  // A brick with a loop of its own (an 11-term series): its trip count is found too.
  auto [th, bh] = kernels("horizon_wrap_accurate", 4);
  CHECK(staticCost(th).loopsWithUnknownTripCount == 0);
  // Known orderings: GGX is rational where Beckmann needs an exp; the fast correlated Smith
  // drops two square roots; Schlick's Fresnel is one pow5 against the exact dielectric's
  // square roots and divisions.
  INFO("d_ggx " << ggx4 << ", d_beckmann " << perEval("d_beckmann", 4));
  CHECK(ggx4 > 0);
  CHECK(ggx4 < perEval("d_beckmann", 4));
  CHECK(perEval("v_smith_ggx_correlated_fast", 4) < perEval("v_smith_ggx_correlated", 4));
  CHECK(perEval("f_schlick", 4) < perEval("f_dielectric_exact", 4));
  CHECK_THROWS(staticCost({1, 2, 3}));
}

TEST_CASE("static cost: every shipped brick costs more than nothing", "[bench]") {
  // Even a brick that returns a constant pays the add that accumulates its result, so a
  // cost of 0 or below means the definition subtracts something the brick never had.
  const ShaderLibrary& lib = test::shippedLibrary();
  REQUIRE(!lib.bricks().empty());
  for (const Brick& b : lib.bricks()) {
    EmittedShader t = emitBrickBenchProbe(lib, b, {4, false});
    const double c = staticCostPerEvaluation(compileComputeGlsl(t.glsl, t.fileName).spirv);
    INFO(b.id << ": static cost " << c);
    CHECK(c > 0);
  }
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
  // A permutation without the directional light, with an area light and an environment: the
  // bench kernel times what validation runs, every light and the environment (it once timed
  // one directional light whatever the permutation, and did not compile without it).
  Permutation lit = perm;
  lit.lights = {LightType::Sphere, LightType::Rect};
  lit.environment = EnvironmentMode::Sh;
  cases.push_back({buildPermutationProbe(lib, lit), emitPermutationBenchProbe(lib, lit, {iterations, false}),
                   emitPermutationBenchProbe(lib, lit, {iterations, true})});
  for (const Case& c : cases) {
    const ProbeLayout& layout = c.probe.shader.layout;
    INFO(c.timed.key);
    ProbeRun run = runProbe(gpu, c.probe, generateSamples(layout, c.probe.domain, 64, 5));
    auto kernelOut = [&](const EmittedShader& s) {
      auto k = gpu.createKernel(compileComputeGlsl(s.glsl, s.fileName).spirv, 0, s.readsTable);
      return gpu.run(*k, run.inputs, layout.inStride, layout.outStride, run.count, {}, c.probe.tableBuffer()).outputs;
    };
    std::vector<float> timed = kernelOut(c.timed), base = kernelOut(c.baseline);
    for (uint64_t i = 0; i < run.count; ++i) {
      // The inputs move by at most (iterations - 1) 2^-20 relative: the mean of the timed
      // loop is the probe's value to ~1e-5 relative (GGX D's sensitivity to alpha is <= ~4),
      // plus the problem's own sensitivity to the ulp-level direction changes that scaling
      // n, v, l before normalizing brings (the conditioning validate allows for), plus twice
      // the probe's validated tolerance: the loop is another compilation of the same function,
      // and each is within that tolerance of the reference (the area lights' polygon integrals
      // round differently when the compiler contracts them in the loop: 1e-4 absolute seen).
      const Tolerance& tol = c.probe.tolerance;
      for (uint32_t k = 0; k < layout.outStride; ++k) {
        size_t at = i * layout.outStride + k;
        double probe = run.gpu[at], mean = timed[at] / iterations;
        CHECK(std::abs(mean - probe) <=
              1e-3 * std::abs(probe) + 1e-6 + 2.0 * run.conditioning[at] + 2.0 * (tol.abs + tol.rel * std::abs(probe)));
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
    CHECK_FALSE(it.cost.resolved);  // one repeat gives no 95 % interval: below resolution
    CHECK(it.cost.nsUpperBound() > 0);
    CHECK(it.cost.iterations == 4);  // fixed: no calibration
    CHECK(it.staticCost > 0);
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
  CHECK(csv.find(",d_ggx,brick,,,,") != std::string::npos);  // no value for a cost below resolution
  std::string md = toMarkdown(r);
  CHECK(md.find("### `specular_d`") != std::string::npos);
  CHECK(md.find("| below resolution (< ") != std::string::npos);
  CHECK(j["groups"][0]["items"][0]["ns_per_eval"].is_null());
  CHECK(j["groups"][0]["items"][0]["cost"]["ns_per_eval_below"].get<double>() > 0);
  std::string doc = std::string("intro\n") + kMarkdownBegin + "\nold\n" + kMarkdownEnd + "\ntail\n";
  CHECK(spliceGenerated(doc, "new\n") ==
        std::string("intro\n") + kMarkdownBegin + "\nnew\n" + kMarkdownEnd + "\ntail\n");
  requireNoLayerMessages(gpu);
}

TEST_CASE("matbricks bench writes its outputs and rejects unknown names", "[bench][cli][vulkan]") {
  auto dir = test::freshTempDir("test_bench", "cli");
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

TEST_CASE("light methods: LTC is nearer the integral than the representative point and costs more", "[bench][vulkan]") {
  // bench_engine/light_methods.hpp on spheres: the errors are deterministic (double, seeded),
  // the costs measured; what is asserted of the costs is their order, far apart on any device
  // (the LTC integration against a few dozen operations).
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  const ShaderLibrary& lib = test::shippedLibrary();
  const MaterialDesc m = loadMaterialJson(test::materialPath("filament_plastic.json"), lib);
  REQUIRE(bench::hasLightMethods(lib, m));
  bench::LightMethodOptions o;
  o.lights = 60;
  o.cost.repeats = 6;
  o.cost.targetDispatchMs = 0.5;
  const auto rows = bench::measureLightMethods(gpu, lib, m, o, {LightType::Sphere});
  REQUIRE(rows.size() == 2);
  CHECK(bench::lightMethodLabel(rows[0]) == "sphere: ltc");
  CHECK(rows[0].readsLtcTable);
  CHECK(!rows[1].readsLtcTable);
  INFO("ltc " << rows[0].errorMedian << " / " << rows[0].cost.nsPerEval << " ns, representative point "
              << rows[1].errorMedian << " / " << rows[1].cost.nsPerEval << " ns");
  CHECK(rows[0].errorMedian < rows[1].errorMedian);
  CHECK(rows[0].cost.nsPerEvalLow > rows[1].cost.nsPerEvalHigh);
  requireNoLayerMessages(gpu);
}
