// Run time of a bench probe on the Vulkan device: timestamped dispatches (the harness's
// gpuMs), the median over repeats, the empty-loop baseline subtracted
// (emit/bench_probe.hpp explains the two kernels).
#pragma once
#include <cstdint>
#include <vector>

#include "compile/glsl_compiler.hpp"
#include "harness/vulkan_harness.hpp"
#include "validate/sampler.hpp"

namespace mb::bench {

struct CostOptions {
  uint32_t repeats = 9;
  uint64_t records = 0;      // records per dispatch; 0 = calibrate to targetDispatchMs
  uint32_t iterations = 64;  // evaluations per record, as emitted into both kernels
  double targetDispatchMs = 5;
  uint64_t seed = 1;
};

struct CostMeasurement {
  double nsPerEval = 0;   // median over repeats of (timed - baseline) / evaluations
  double nsRaw = 0;       // median timed dispatch / evaluations
  double nsBaseline = 0;  // median baseline dispatch / evaluations
  // (fastest timed - fastest baseline) / evaluations: on a loaded machine time is only ever
  // added to a dispatch, so the minima are the other robust estimate; reported beside.
  double nsPerEvalMin = 0;
  uint64_t records = 0;       // per dispatch
  uint64_t evaluations = 0;   // per dispatch: records * iterations
  bool gpuTimestamps = true;  // false: the harness fell back to host time
};

double median(std::vector<double> v);

// Creates both kernels, warms them up (lavapipe JIT-compiles at the first dispatch, which
// the timestamps would otherwise include), calibrates the record count when asked, then
// alternates baseline and timed dispatches so that both see the same machine load.
CostMeasurement measureCost(harness::VulkanHarness& gpu, const CompileResult& timed, const CompileResult& baseline,
                            const ProbeLayout& layout, const SampleDomain& domain, const CostOptions& options);

}  // namespace mb::bench
