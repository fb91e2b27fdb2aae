// matbricks bench: run time against error, per slot (DESIGN.md: the LEGO property makes it a
// per-slot table), for every example material permutation, and for the DFG LUT choices.
// Every shader is built by the probe machinery (validate/probe_program.hpp) and the bench
// probe emitter (emit/bench_probe.hpp); nothing here writes GLSL.
#pragma once
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "bench_engine/cost.hpp"
#include "bench_engine/error_summary.hpp"
#include "core/progress_sink.hpp"
#include "emit/bench_probe.hpp"
#include "library/shader_library.hpp"
#include "load/material_desc.hpp"
#include "lut/dfg_lut.hpp"
#include "permute/permutation.hpp"
#include "validate/error_metrics.hpp"
#include "validate/probe_program.hpp"

namespace mb::bench {

struct BenchOptions {
  std::vector<std::string> slots;   // only these slots (empty: every slot)
  std::vector<std::string> bricks;  // only these bricks (empty: every brick of the slots)
  bool includeBricks = true;        // false: materials and/or IBL only
  uint64_t samples = 4096;          // error samples per brick / permutation / LUT
  uint64_t seed = 1;
  CostOptions cost;
  std::vector<uint32_t> lutSizes;  // DFG LUT sizes for the IBL table (empty: none)
};

struct BenchItem {
  std::string id;    // brick id, or permutation key
  std::string kind;  // "brick" or "permutation"
  CostMeasurement cost;
  // bench_engine/static_cost.hpp: one iteration of the optimized timed kernel's loop less its
  // counter, weighted by throughput (fp32 FMA issue slots). Deterministic, always > 0.
  double staticCost = 0;
  size_t spirvInstructions = 0;                // the probe's, after spirv-opt (as validate reports it)
  std::string yardstick;                       // "ground_truth" or "reference"
  std::vector<std::string> groundTruthBricks;  // permutations: bricks replaced by their truth
  std::string truthNote;                       // bricks: Brick::truthNote (not cached: the manifest's)
  ErrorSummary error;                          // GPU output against the yardstick
  ErrorStats vsReference;                      // GPU output against the brick's own reference (fp32 error)
  bool onFrontier = false;
  // Off the frontier only because its cost is not significantly different from this
  // frontier item's, which is at least as accurate (bench_engine/pareto.hpp); empty otherwise.
  std::string tiedWith;
};

// One chart: the bricks of a slot, or the example materials' permutations.
struct BenchGroup {
  std::string name;  // slot name, or "materials"
  std::vector<BenchItem> items;
};

struct LutItem {
  uint32_t size = 0;
  lut::LutFormat format = lut::LutFormat::Fp32;
  uint64_t bytes = 0;
  ErrorSummary error;  // against the integrated split-sum, like the env_brdf bricks
};

struct IblSection {
  std::string samplesFrom;  // the brick whose layout and domain gave the samples
  uint64_t samples = 0;
  std::vector<LutItem> luts;
};

struct BenchReport {
  std::string device;
  std::string toolchain;
  BenchOptions options;
  std::vector<BenchGroup> groups;
  bool hasIbl = false;
  IblSection ibl;
};

// Writes the timed or the empty-loop bench kernel (emit/bench_probe.hpp) for some iterations.
using BenchKernelEmitter = std::function<EmittedShader(const BenchProbeOptions&)>;

struct BenchCost {
  CostMeasurement measured;
  double staticCost = 0;  // BenchItem::staticCost
};
// The measured cost (bench_engine/cost.hpp, calibrating the iterations by recompiling the kernels)
// and the static cost of the final kernels, on the probe's layout and sample domain.
BenchCost measureBenchCost(harness::VulkanHarness& gpu, const ProbeProgram& probe, const BenchKernelEmitter& emit,
                           const CostOptions& options);
// The same for a material permutation (bench's materials, the report, mb_bench_compile).
BenchCost measurePermutationCost(harness::VulkanHarness& gpu, const ShaderLibrary& lib, const Permutation& perm,
                                 const ProbeProgram& probe, const CostOptions& options);

// Marks the Pareto frontier of (ns per evaluation, max scaled error) in `group`, over the
// items measured against a ground truth if there are any, else over all: costs compared by
// their confidence intervals (a cost below resolution is [0, its bound]), ties marked.
void markFrontier(BenchGroup& group);

// Brick items measured by an earlier run (the report's result cache, core/result_cache.hpp):
// `find` gives the item of a brick whose probe is `probe`, or nothing; `keep` is handed each
// brick item runBench measured itself.
struct BrickItemMemo {
  std::function<std::optional<BenchItem>(const Brick&, const ProbeProgram& probe)> find;
  std::function<void(const Brick&, const ProbeProgram& probe, const BenchItem&)> keep;
};

// `progress` (may be null) counts one unit per measured item (brick, permutation, LUT).
// `memo` (may be null) supplies brick items instead of measuring them.
BenchReport runBench(const ShaderLibrary& lib, harness::VulkanHarness& gpu, const std::vector<MaterialDesc>& materials,
                     const BenchOptions& options, ProgressSink* progress, const BrickItemMemo* memo = nullptr);

}  // namespace mb::bench
