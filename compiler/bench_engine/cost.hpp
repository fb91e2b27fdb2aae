// Run time of a bench probe on the Vulkan device: timestamped dispatches (the harness's
// gpuMs) of the timed kernel and of the empty loop (emit/bench_probe.hpp explains the two
// kernels), paired repeat by repeat; the cost is the median of the paired differences per
// evaluation, with a distribution-free confidence interval (bench_engine/cost_interval.hpp).
//
// Calibration (docs/accuracy.md "How cost is measured"): the records per dispatch first,
// up to what fills the device (kMaxRecords) or the target dispatch time; then the
// evaluations per record (iterations, compiled into both kernels), until the kernel's time
// clearly exceeds the empty loop's: the paired difference must reach kClearMargin times the
// larger of the timer's resolution over a dispatch (2 timestamp periods per chunk) and the
// empty loop's own spread (max - min over the pilot repeats). A fast GPU finishes 2^18 records
// of 64 evaluations in microseconds, where launch noise is of the same size: there it is the
// iterations that grow, not the records (which are bounded by memory).
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "compile/glsl_compiler.hpp"
#include "harness/vulkan_harness.hpp"
#include "validate/sampler.hpp"

namespace mb::bench {

struct CostOptions {
  uint32_t repeats = 9;     // paired dispatches measured (>= 6 for a 95 % interval)
  uint64_t records = 0;     // records per dispatch; 0 = calibrate to targetDispatchMs
  uint32_t iterations = 0;  // evaluations per record; 0 = calibrate from kStartIterations
  double targetDispatchMs = 5;
  // Calibration stops growing the iterations once a timed dispatch would exceed this
  // (0: 10 x targetDispatchMs); what is then not resolved is reported as such.
  double maxDispatchMs = 0;
  uint64_t seed = 1;
  // spirv-opt's level for the timed kernels (`bench -O`, as `compile -O`): what a level costs
  // at run time. The probe that measures the error is validate's, at O2.
  OptimizationLevel optimization = OptimizationLevel::O2;
};

inline constexpr uint32_t kStartIterations = 64;
// Inputs are scaled by (1 - k 2^-20) in iteration k: 4096 iterations move them by < 0.4 %.
inline constexpr uint32_t kMaxIterations = 4096;
inline constexpr double kClearMargin = 10;

struct CostMeasurement {
  // Per evaluation, from the paired differences (timed - baseline) of the repeats: their
  // median and its confidence interval. Only meaningful (and only ever printed) when
  // `resolved`; internally they may be 0 or negative.
  double nsPerEval = 0;
  double nsPerEvalLow = 0, nsPerEvalHigh = 0;
  double confidence = 0;        // exact coverage of [low, high]
  bool resolved = false;        // bench_engine/cost_interval.hpp separatedFromEmptyLoop
  double nsResolution = 0;      // the timer's resolution over one dispatch, per evaluation
  double nsBaselineSpread = 0;  // max - min of the empty loop's dispatches, per evaluation
  double nsRaw = 0;             // median timed dispatch / evaluations
  double nsBaseline = 0;        // median baseline dispatch / evaluations
  uint64_t records = 0;         // per dispatch
  uint32_t iterations = 0;      // per record, after calibration
  uint64_t evaluations = 0;     // per dispatch: records * iterations
  uint32_t calibrationRounds = 0;
  bool gpuTimestamps = true;  // false: the harness fell back to host time

  // What the measurement bounds the cost by: the interval's top, at least the resolution.
  double nsUpperBound() const;
};

double median(std::vector<double> v);

struct KernelPair {
  std::vector<uint32_t> timed, baseline;  // SPIR-V of the two bench kernels
  // The table both read (a permutation with rectangle or disk lights: its LTC table), or null.
  const std::vector<float>* table = nullptr;
};
// The two kernels compiled for a number of evaluations per record.
using KernelPairFactory = std::function<KernelPair(uint32_t iterations)>;

// Warms both kernels up (lavapipe JIT-compiles at the first dispatch, which the timestamps
// would otherwise include), calibrates records and iterations as above, then alternates
// baseline and timed dispatches (in ABBA order, so that a drifting load hits both alike).
CostMeasurement measureCost(harness::VulkanHarness& gpu, const KernelPairFactory& kernels, const ProbeLayout& layout,
                            const SampleDomain& domain, const CostOptions& options);

}  // namespace mb::bench
