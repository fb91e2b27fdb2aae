#include "bench_engine/bench_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>

#include "bench_engine/ibl_bench.hpp"
#include "bench_engine/pareto.hpp"
#include "bench_engine/static_cost.hpp"
#include "bench_engine/yardstick.hpp"
#include "core/parallel.hpp"
#include "emit/bench_probe.hpp"
#include "permute/permutation.hpp"
#include "validate/probe_program.hpp"

namespace mb::bench {
namespace {

bool selected(const std::vector<std::string>& filter, const std::string& name) {
  return filter.empty() || std::find(filter.begin(), filter.end(), name) != filter.end();
}

ErrorSummary errorAgainst(const ProbeRun& run, const ProbeLayout& layout, const Yardstick& y) {
  std::vector<double> truth(run.count * layout.outStride);
  parallelFor(run.count, [&](size_t i) {
    std::vector<double> record(run.inputs.begin() + i * layout.inStride,
                               run.inputs.begin() + (i + 1) * layout.inStride);
    y.eval(record.data(), truth.data() + i * layout.outStride);
  });
  ErrorSummary e;
  for (size_t k = 0; k < truth.size(); ++k) e.add(run.gpu[k], truth[k]);
  return e;
}

// Cost of the bench kernels (measured and static), instruction count of the probe, error of
// the probe's GPU output. `emit(options)` writes the timed or the baseline bench kernel.
BenchItem measure(harness::VulkanHarness& gpu, const ProbeProgram& probe, const BenchKernelEmitter& emit,
                  const Yardstick& yardstick, const BenchOptions& o) {
  BenchItem item;
  item.id = probe.shader.key;
  item.spirvInstructions = spirvInstructionCount(probe.compiled.spirv);
  BenchCost cost = measureBenchCost(gpu, probe, emit, o.cost);
  item.cost = cost.measured;
  item.staticCost = cost.staticCost;
  ProbeRun run = runProbe(gpu, probe, generateSamples(probe.shader.layout, probe.domain, o.samples, o.seed));
  item.vsReference = compare(run, probe);
  item.yardstick = yardstick.kind;
  item.groundTruthBricks = yardstick.groundTruthBricks;
  item.error = errorAgainst(run, probe.shader.layout, yardstick);
  return item;
}

}  // namespace

BenchCost measureBenchCost(harness::VulkanHarness& gpu, const ProbeProgram& probe, const BenchKernelEmitter& emit,
                           const CostOptions& options) {
  KernelPair last;
  BenchCost c;
  c.measured = measureCost(
      gpu,
      [&](uint32_t iterations) {
        EmittedShader timed = emit({iterations, false}), base = emit({iterations, true});
        CompileOptions level;
        level.optimization = options.optimization;
        last = {compileComputeGlsl(timed.glsl, timed.fileName, level).spirv,
                compileComputeGlsl(base.glsl, base.fileName, level).spirv, probe.tableBuffer()};
        return last;
      },
      probe.shader.layout, probe.domain, options);
  c.staticCost = staticCostPerEvaluation(last.timed);
  return c;
}

BenchCost measurePermutationCost(harness::VulkanHarness& gpu, const ShaderLibrary& lib, const Permutation& perm,
                                 const ProbeProgram& probe, const CostOptions& options) {
  return measureBenchCost(
      gpu, probe, [&](const BenchProbeOptions& k) { return emitPermutationBenchProbe(lib, perm, k); }, options);
}

void markFrontier(BenchGroup& group) {
  // One yardstick per chart: where some items are measured against a ground truth, an item
  // measured only against its own reference (its fp32 error, not an approximation error)
  // is not comparable and stays off the frontier.
  bool anyTruth = std::any_of(group.items.begin(), group.items.end(),
                              [](const BenchItem& it) { return it.yardstick == "ground_truth"; });
  std::vector<ParetoPoint> points;
  for (const auto& it : group.items) {
    const CostMeasurement& c = it.cost;
    points.push_back({c.nsPerEval, anyTruth && it.yardstick != "ground_truth" ? NAN : it.error.maxScaled(),
                      c.resolved ? c.nsPerEvalLow : 0.0, c.resolved ? c.nsPerEvalHigh : c.nsUpperBound()});
  }
  FrontierMarks marks = paretoFrontierWithTies(points);
  for (auto& it : group.items) it.onFrontier = false, it.tiedWith.clear();
  for (size_t i : marks.frontier) group.items[i].onFrontier = true;
  for (size_t i = 0; i < points.size(); ++i)
    if (marks.tiedWith[i]) group.items[i].tiedWith = group.items[*marks.tiedWith[i]].id;
}

BenchReport runBench(const ShaderLibrary& lib, harness::VulkanHarness& gpu, const std::vector<MaterialDesc>& materials,
                     const BenchOptions& o, ProgressSink* progress, const BrickItemMemo* memo) {
  BenchReport rep;
  rep.device = gpu.deviceName();
  rep.toolchain = toolchainVersion();
  rep.options = o;
  const std::vector<Permutation> perms = permutationsFor(materials);
  if (progress) {
    size_t units = perms.size();
    for (const auto& slot : lib.slots())
      if (o.includeBricks && selected(o.slots, slot.name))
        for (const auto& id : lib.bricksOfSlot(slot.name)) units += selected(o.bricks, id);
    progress->addToTotal(units);
  }

  for (const auto& slot : lib.slots()) {
    if (!o.includeBricks || !selected(o.slots, slot.name)) continue;
    BenchGroup group{slot.name, {}};
    for (const auto& id : lib.bricksOfSlot(slot.name)) {
      if (!selected(o.bricks, id)) continue;
      const Brick& b = *lib.findBrick(id);
      const ProbeProgram probe = buildBrickProbe(lib, b);
      std::optional<BenchItem> earlier = memo ? memo->find(b, probe) : std::nullopt;
      if (earlier) {
        group.items.push_back(std::move(*earlier));
      } else {
        group.items.push_back(measure(
            gpu, probe, [&](const BenchProbeOptions& k) { return emitBrickBenchProbe(lib, b, k); }, brickYardstick(b),
            o));
        group.items.back().id = id;
        group.items.back().kind = "brick";
        if (memo) memo->keep(b, probe, group.items.back());
      }
      group.items.back().truthNote = b.truthNote;
      if (progress) progress->advance();
    }
    if (group.items.empty()) continue;
    markFrontier(group);
    rep.groups.push_back(std::move(group));
  }

  BenchGroup mats{"materials", {}};
  for (const auto& perm : perms) {
    ProbeProgram probe = buildPermutationProbe(lib, perm);
    mats.items.push_back(measure(
        gpu, probe, [&](const BenchProbeOptions& k) { return emitPermutationBenchProbe(lib, perm, k); },
        materialYardstick(*perm.material, probe.shader.layout, probe.ltcTable), o));
    mats.items.back().kind = "permutation";
    if (progress) progress->advance();
  }
  if (!mats.items.empty()) {
    markFrontier(mats);
    rep.groups.push_back(std::move(mats));
  }

  if (!o.lutSizes.empty()) rep.hasIbl = measureDfgLuts(lib, o, rep.ibl, progress);
  return rep;
}

}  // namespace mb::bench
