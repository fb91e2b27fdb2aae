#include "bench/cost.hpp"

#include <algorithm>

namespace mb::bench {
namespace {

// Enough records to fill lavapipe's threads many times over, few enough that the inputs
// (up to ~22 floats a record) stay well under 100 MB.
constexpr uint64_t kMinRecords = 256;
constexpr uint64_t kMaxRecords = uint64_t{1} << 18;
constexpr uint64_t kCalibrationRecords = 2048;

uint64_t roundUpToGroup(uint64_t n) { return (n + 63) / 64 * 64; }

}  // namespace

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

CostMeasurement measureCost(harness::VulkanHarness& gpu, const CompileResult& timed, const CompileResult& baseline,
                            const ProbeLayout& layout, const SampleDomain& domain, const CostOptions& o) {
  auto timedKernel = gpu.createKernel(timed.spirv);
  auto baseKernel = gpu.createKernel(baseline.spirv);
  CostMeasurement m;
  m.records = o.records ? o.records : kCalibrationRecords;
  std::vector<float> inputs = generateSamples(layout, domain, m.records, o.seed);
  auto run = [&](harness::Kernel& k) {
    harness::RunResult r = gpu.run(k, inputs, layout.inStride, layout.outStride, m.records);
    m.gpuTimestamps = m.gpuTimestamps && r.gpuTimestamps;
    return r.gpuMs;
  };
  run(*baseKernel);                        // JIT warm-up
  double calibration = run(*timedKernel);  // JIT warm-up
  if (o.records == 0) {
    calibration = run(*timedKernel);
    double scale = o.targetDispatchMs / std::max(calibration, 1e-3);
    uint64_t want = roundUpToGroup(static_cast<uint64_t>(double(m.records) * scale));
    want = std::clamp(want, kMinRecords, kMaxRecords);
    if (want != m.records) {
      m.records = want;
      inputs = generateSamples(layout, domain, m.records, o.seed);
    }
  }
  m.evaluations = m.records * o.iterations;
  std::vector<double> timedMs, baseMs, netMs;
  for (uint32_t r = 0; r < std::max(o.repeats, 1u); ++r) {
    baseMs.push_back(run(*baseKernel));
    timedMs.push_back(run(*timedKernel));
    netMs.push_back(timedMs.back() - baseMs.back());
  }
  const double toNs = 1e6 / double(m.evaluations);
  m.nsRaw = median(timedMs) * toNs;
  m.nsBaseline = median(baseMs) * toNs;
  m.nsPerEval = median(netMs) * toNs;
  m.nsPerEvalMin =
      (*std::min_element(timedMs.begin(), timedMs.end()) - *std::min_element(baseMs.begin(), baseMs.end())) * toNs;
  return m;
}

}  // namespace mb::bench
