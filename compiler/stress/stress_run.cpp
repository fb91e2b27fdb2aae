#include "stress/stress_run.hpp"

#include <cmath>
#include <cstdio>

#include "stress/stress_inputs.hpp"

namespace mb {

void StressStats::add(int64_t record, float gpu, double ref) {
  ++values;
  if (!std::isfinite(ref)) {
    ++referenceUndefined;
    return;
  }
  if (std::isinf(gpu) && std::abs(ref) > maxFinite && (gpu > 0) == (ref > 0)) {
    ++overflowCount;
    return;
  }
  if (!std::isfinite(gpu)) {
    (std::isnan(gpu) ? nanCount : infCount)++;
    if (!worstIsNonFinite) {
      worstIsNonFinite = true;
      worstRecord = record;
    }
    return;
  }
  if (gpu < 0.0f) ++negativeCount;
  double err = std::abs(static_cast<double>(gpu) - ref);
  double rel = err / std::max(std::abs(ref), kRelativeErrorFloor);
  maxAbs = std::max(maxAbs, err);
  if (rel > maxRel || worstRecord < 0) {
    maxRel = std::max(maxRel, rel);
    if (!worstIsNonFinite) worstRecord = record;
  }
}

std::string csvRow(const std::vector<std::string>& columns, const std::vector<float>& row) {
  std::string header, values;
  char buf[32];
  for (size_t k = 0; k < columns.size(); ++k) {
    std::snprintf(buf, sizeof buf, "%.9g", row[k]);  // 9 digits round-trip any fp32 value
    header += (k ? "," : "") + columns[k];
    values += std::string(k ? "," : "") + buf;
  }
  return header + "\n" + values + "\n";
}

StressResult stressProbe(harness::VulkanHarness& gpu, const ProbeProgram& program, const std::string& kind,
                         const std::string& id, const StressOptions& options) {
  const ProbeLayout& layout = program.shader.layout;
  StressResult res;
  res.key = program.shader.key;
  res.fp16Mode = program.fp16Mode;
  res.kind = kind;
  res.id = id;
  res.precision = program.precision;
  res.columns = layout.columns();
  if (program.precision == ShaderPrecision::Fp16) res.inDomain.maxFinite = res.outOfDomain.maxFinite = 65504.0;

  StressInputs inputs =
      generateStressInputs(layout, program.domain, program.precision, options.randomSamples, options.seed);
  std::vector<uint8_t> inDomain = inputs.inDomain;
  // Stress reports raw errors (no tolerance), so the conditioning allowance is not needed.
  ProbeRun run = runProbe(gpu, program, std::move(inputs.records), /*conditioning=*/false);
  const uint32_t os = layout.outStride, is = layout.inStride;
  for (uint64_t i = 0; i < run.count; ++i) {
    StressStats& s = inDomain[i] ? res.inDomain : res.outOfDomain;
    ++s.records;
    for (uint32_t k = 0; k < os; ++k) s.add(static_cast<int64_t>(i), run.gpu[i * os + k], run.reference[i * os + k]);
  }
  auto row = [&](int64_t r) {
    return r < 0 ? std::vector<float>{}
                 : std::vector<float>(run.inputs.begin() + r * is, run.inputs.begin() + (r + 1) * is);
  };
  res.worstInDomainRow = row(res.inDomain.worstRecord);
  res.worstOutOfDomainRow = row(res.outOfDomain.worstRecord);
  if (int64_t r = res.inDomain.worstRecord; r >= 0) {
    res.worstInDomainGpu.assign(run.gpu.begin() + r * os, run.gpu.begin() + (r + 1) * os);
    res.worstInDomainReference.assign(run.reference.begin() + r * os, run.reference.begin() + (r + 1) * os);
  }
  return res;
}

}  // namespace mb
