#include "bench_engine/cost.hpp"

#include <algorithm>
#include <chrono>

#include "bench_engine/cost_interval.hpp"

namespace mb::bench {
namespace {

// Enough records to fill lavapipe's threads many times over (and 2^18 fills an H100's
// 132 x 2048 resident threads), few enough that the inputs (up to ~22 floats a record) stay
// well under 100 MB.
constexpr uint64_t kMinRecords = 256;
constexpr uint64_t kMaxRecords = uint64_t{1} << 18;
constexpr uint64_t kCalibrationRecords = 2048;
constexpr uint32_t kPilotPairs = 3;
constexpr uint32_t kMaxCalibrationRounds = 3;

uint64_t roundUpToGroup(uint64_t n) { return (n + 63) / 64 * 64; }

uint32_t roundUpToPowerOfTwo(double x) {
  uint32_t p = 1;
  while (p < kMaxIterations && double(p) < x) p *= 2;
  return p;
}

struct Dispatch {
  double ms = 0;
  uint32_t chunks = 1;
};

class Session {
 public:
  Session(harness::VulkanHarness& gpu, const std::vector<float>& inputs, const ProbeLayout& layout, uint64_t records,
          CostMeasurement& m)
      : gpu_(gpu), inputs_(inputs), layout_(layout), records_(records), m_(m) {}

  void load(const KernelPair& pair) {
    table_ = pair.table;
    timed_ = gpu_.createKernel(pair.timed, 0, table_ != nullptr);
    base_ = gpu_.createKernel(pair.baseline, 0, table_ != nullptr);
    run(*base_);  // JIT warm-up
    run(*timed_);
  }
  void setRecords(uint64_t records) { records_ = records; }
  Dispatch timed() { return run(*timed_); }
  Dispatch baseline() { return run(*base_); }

 private:
  Dispatch run(harness::Kernel& k) {
    harness::RunResult r = gpu_.run(k, inputs_, layout_.inStride, layout_.outStride, records_, {}, table_);
    m_.gpuTimestamps = m_.gpuTimestamps && r.gpuTimestamps;
    return {r.gpuMs, std::max(r.chunks, 1u)};
  }
  harness::VulkanHarness& gpu_;
  const std::vector<float>& inputs_;
  const ProbeLayout& layout_;
  uint64_t records_;
  CostMeasurement& m_;
  std::shared_ptr<harness::Kernel> timed_, base_;
  const std::vector<float>* table_ = nullptr;
};

// Paired samples in ms: `order` alternates ABBA so that a load drifting over the repeats
// weighs on the baseline and the timed kernel alike.
struct Pairs {
  std::vector<double> timed, base, net;
  uint32_t chunks = 1;
};
Pairs measurePairs(Session& s, uint32_t n) {
  Pairs p;
  for (uint32_t r = 0; r < n; ++r) {
    Dispatch b, t;
    if (r % 2 == 0) {
      b = s.baseline();
      t = s.timed();
    } else {
      t = s.timed();
      b = s.baseline();
    }
    p.base.push_back(b.ms);
    p.timed.push_back(t.ms);
    p.net.push_back(t.ms - b.ms);
    p.chunks = std::max(b.chunks, t.chunks);
  }
  return p;
}

}  // namespace

double median(std::vector<double> v) { return medianInterval(std::move(v)).median; }

double CostMeasurement::nsUpperBound() const { return std::max(nsPerEvalHigh, nsResolution); }

CostMeasurement measureCost(harness::VulkanHarness& gpu, const KernelPairFactory& kernels, const ProbeLayout& layout,
                            const SampleDomain& domain, const CostOptions& o) {
  CostMeasurement m;
  m.iterations = o.iterations ? o.iterations : kStartIterations;
  m.records = o.records ? o.records : kCalibrationRecords;
  std::vector<float> inputs = generateSamples(layout, domain, m.records, o.seed);
  Session session(gpu, inputs, layout, m.records, m);
  session.load(kernels(m.iterations));

  if (o.records == 0) {
    double calibration = session.timed().ms;
    double scale = o.targetDispatchMs / std::max(calibration, 1e-3);
    uint64_t want =
        std::clamp(roundUpToGroup(static_cast<uint64_t>(double(m.records) * scale)), kMinRecords, kMaxRecords);
    if (want != m.records) {
      m.records = want;
      inputs = generateSamples(layout, domain, m.records, o.seed);
      session.setRecords(m.records);
    }
  }

  // Timer resolution over a dispatch, in ms: each chunk's interval is a difference of two
  // timestamps, each quantized to a tick, and the net cost a difference of two intervals.
  const double tickNs =
      m.gpuTimestamps ? std::max(gpu.timestampPeriodNs(), 1e-3)
                      : 1e9 * double(std::chrono::steady_clock::period::num) / std::chrono::steady_clock::period::den;
  auto resolutionMs = [&](uint32_t chunks) { return 2.0 * tickNs * chunks / 1e6; };
  const double maxMs = o.maxDispatchMs > 0 ? o.maxDispatchMs : 10 * o.targetDispatchMs;

  if (o.iterations == 0) {
    for (uint32_t round = 0; round < kMaxCalibrationRounds; ++round) {
      Pairs pilot = measurePairs(session, kPilotPairs);
      const double spread = *std::max_element(pilot.base.begin(), pilot.base.end()) -
                            *std::min_element(pilot.base.begin(), pilot.base.end());
      const double need = kClearMargin * std::max(resolutionMs(pilot.chunks), spread);
      const double net = median(pilot.net), timed = median(pilot.timed);
      if (net >= need) break;
      // Net time grows in proportion to the iterations; 25 % headroom, at most 16x a round
      // when the difference is not even positive yet, and never past the dispatch cap.
      double factor = net > 0 ? 1.25 * need / net : 16.0;
      factor = std::min(factor, maxMs / std::max(timed, 1e-6));
      uint32_t want = std::min(kMaxIterations, roundUpToPowerOfTwo(double(m.iterations) * factor));
      if (want <= m.iterations) break;
      m.iterations = want;
      session.load(kernels(m.iterations));
      ++m.calibrationRounds;
    }
  }
  m.evaluations = m.records * m.iterations;

  Pairs p = measurePairs(session, std::max(o.repeats, 1u));
  const double toNs = 1e6 / double(m.evaluations);  // ms per dispatch -> ns per evaluation
  MedianInterval net = medianInterval(p.net);
  m.resolved = separatedFromEmptyLoop(net, resolutionMs(p.chunks));
  m.confidence = net.confidence;
  m.nsPerEval = net.median * toNs;
  m.nsPerEvalLow = net.low * toNs;
  m.nsPerEvalHigh = net.high * toNs;
  m.nsResolution = resolutionMs(p.chunks) * toNs;
  m.nsBaselineSpread =
      (*std::max_element(p.base.begin(), p.base.end()) - *std::min_element(p.base.begin(), p.base.end())) * toNs;
  m.nsRaw = median(p.timed) * toNs;
  m.nsBaseline = median(p.base) * toNs;
  return m;
}

}  // namespace mb::bench
