#include "bench/bench_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "bench/ibl_bench.hpp"
#include "bench/parallel.hpp"
#include "bench/pareto.hpp"
#include "bench/yardstick.hpp"
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

// Cost of the bench kernels, instruction count of the probe, error of the probe's GPU output.
BenchItem measure(harness::VulkanHarness& gpu, const ProbeProgram& probe, const EmittedShader& timed,
                  const EmittedShader& baseline, const Yardstick& yardstick, const BenchOptions& o) {
  BenchItem item;
  item.id = probe.shader.key;
  item.spirvInstructions = spirvInstructionCount(probe.compiled.spirv);
  item.cost =
      measureCost(gpu, compileComputeGlsl(timed.glsl, timed.fileName),
                  compileComputeGlsl(baseline.glsl, baseline.fileName), probe.shader.layout, probe.domain, o.cost);
  ProbeRun run = runProbe(gpu, probe, generateSamples(probe.shader.layout, probe.domain, o.samples, o.seed));
  item.vsReference = compare(run, probe);
  item.yardstick = yardstick.kind;
  item.groundTruthBricks = yardstick.groundTruthBricks;
  item.error = errorAgainst(run, probe.shader.layout, yardstick);
  return item;
}

}  // namespace

void markFrontier(BenchGroup& group) {
  // One yardstick per chart: where some items are measured against a ground truth, an item
  // measured only against its own reference (its fp32 error, not an approximation error)
  // is not comparable and stays off the frontier.
  bool anyTruth = std::any_of(group.items.begin(), group.items.end(),
                              [](const BenchItem& it) { return it.yardstick == "ground_truth"; });
  std::vector<ParetoPoint> points;
  for (const auto& it : group.items)
    points.push_back({it.cost.nsPerEval, anyTruth && it.yardstick != "ground_truth" ? NAN : it.error.maxScaled()});
  for (auto& it : group.items) it.onFrontier = false;
  for (size_t i : paretoFrontier(points)) group.items[i].onFrontier = true;
}

BenchReport runBench(const ShaderLibrary& lib, harness::VulkanHarness& gpu, const std::vector<MaterialDesc>& materials,
                     const BenchOptions& o, ProgressSink* progress) {
  BenchReport rep;
  rep.device = gpu.deviceName();
  rep.toolchain = toolchainVersion();
  rep.options = o;
  BenchProbeOptions timedOpt{o.cost.iterations, false}, baseOpt{o.cost.iterations, true};
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
      group.items.push_back(measure(gpu, buildBrickProbe(lib, b), emitBrickBenchProbe(lib, b, timedOpt),
                                    emitBrickBenchProbe(lib, b, baseOpt), brickYardstick(b), o));
      group.items.back().id = id;
      group.items.back().kind = "brick";
      if (progress) progress->advance();
    }
    if (group.items.empty()) continue;
    markFrontier(group);
    rep.groups.push_back(std::move(group));
  }

  BenchGroup mats{"materials", {}};
  for (const auto& perm : perms) {
    ProbeProgram probe = buildPermutationProbe(lib, perm);
    mats.items.push_back(measure(gpu, probe, emitPermutationBenchProbe(lib, perm, timedOpt),
                                 emitPermutationBenchProbe(lib, perm, baseOpt),
                                 materialYardstick(*perm.material, probe.shader.layout), o));
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
