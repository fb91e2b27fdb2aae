#include "validate/validation.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "validate/probe_language.hpp"

namespace mb {
namespace {

// validateProbe with the GPU half given: `runOnDevice(inputs)` runs the kernel on the records.
template <typename RunOnDevice>
ValidationRecord validateWith(const RunOnDevice& runOnDevice, const ProbeProgram& program, const std::string& kind,
                              uint64_t samples, uint64_t seed, const ReferenceOptions& options) {
  ValidationRecord rec;
  rec.key = program.shader.key;
  rec.kind = kind;
  rec.samples = samples;
  rec.tolerance = program.tolerance;
  rec.compileMs = program.compileMs;
  rec.compileCached = program.compileCacheHit;
  rec.spirvInstructions = spirvInstructionCount(program.compiled.spirv);
  ProbeRun run = runOnDevice(generateSamples(program.shader.layout, program.domain, samples, seed));
  rec.gpuMs = run.gpuMs;
  rec.firstDispatchMs = run.firstDispatchMs;
  const auto t0 = std::chrono::steady_clock::now();
  computeReference(run, program, options);
  rec.stats = compare(run, program);
  rec.referenceMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (rec.stats.worstRecord >= 0) {
    auto cols = program.shader.layout.columns();
    std::ostringstream s;
    s.precision(9);
    for (size_t k = 0; k < cols.size(); ++k)
      s << (k ? "," : "") << cols[k] << "=" << run.inputs[rec.stats.worstRecord * cols.size() + k];
    rec.worstInput = s.str();
  }
  return rec;
}

}  // namespace

ValidationRecord validateProbe(harness::VulkanHarness& gpu, const ProbeProgram& program, const std::string& kind,
                               uint64_t samples, uint64_t seed, const ReferenceOptions& options) {
  return validateWith([&](std::vector<float> inputs) { return runProbeOnGpu(gpu, program, std::move(inputs)); },
                      program, kind, samples, seed, options);
}

ValidationRecord validateProbe(const ProbeDevices& devices, const LanguageProbe& probe, const std::string& kind,
                               uint64_t samples, uint64_t seed, const ReferenceOptions& options) {
  return validateWith([&](std::vector<float> inputs) { return runProbeOn(devices, probe, std::move(inputs)); },
                      probe.program, kind, samples, seed, options);
}

nlohmann::json toJson(const ValidationRecord& r) {
  auto num = [](double v) -> nlohmann::json {
    if (std::isfinite(v)) return v;
    return v > 0 ? "inf" : "nan";  // JSON has no Inf
  };
  return {{"key", r.key},
          {"kind", r.kind},
          {"samples", r.samples},
          {"values_compared", r.stats.components},
          {"max_abs_error", num(r.stats.maxAbs)},
          {"max_rel_error", num(r.stats.maxRel)},
          {"rel_error_floor", kRelativeErrorFloor},
          {"max_ulp", num(r.stats.maxUlp)},
          {"nan_count", r.stats.nanCount},
          {"inf_count", r.stats.infCount},
          {"negative_count", r.stats.negativeCount},
          {"negative_fails", r.judgesNegatives()},
          {"reference_invalid_count", r.stats.referenceInvalid},
          {"failures", r.stats.failures},
          {"max_conditioning_allowance", num(r.stats.maxConditioning)},
          {"passed_by_conditioning", r.stats.passedByConditioning},
          {"tolerance", {{"abs", r.tolerance.abs}, {"rel", r.tolerance.rel}, {"reason", r.tolerance.reason}}},
          {"worst_input", r.worstInput},
          {"passed", r.passed()},
          {"compile_ms", r.compileMs},
          {"compile_cached", r.compileCached},
          {"first_dispatch_ms", r.firstDispatchMs},
          {"gpu_ms", r.gpuMs},
          {"reference_ms", r.referenceMs},
          {"spirv_instructions", r.spirvInstructions}};
}

std::string formatValidationTable(const std::vector<ValidationRecord>& records) {
  std::ostringstream s;
  char line[512];
  std::snprintf(line, sizeof line, "%-44s %8s %10s %10s %8s %4s %4s %5s %10s %9s %9s %9s  %s\n", "permutation",
                "samples", "max_abs", "max_rel", "max_ulp", "nan", "inf", "neg", "compile_ms", "jit_ms", "gpu_ms",
                "ref_ms", "result");
  s << line;
  for (const auto& r : records) {
    std::snprintf(line, sizeof line, "%-44s %8llu %10.3g %10.3g %8.3g %4llu %4llu %5llu %10.2f %9.2f %9.3f %9.2f  %s\n",
                  r.key.c_str(), static_cast<unsigned long long>(r.samples), r.stats.maxAbs, r.stats.maxRel,
                  r.stats.maxUlp, static_cast<unsigned long long>(r.stats.nanCount),
                  static_cast<unsigned long long>(r.stats.infCount),
                  static_cast<unsigned long long>(r.stats.negativeCount), r.compileMs, r.firstDispatchMs, r.gpuMs,
                  r.referenceMs, r.passed() ? "PASS" : "FAIL");
    s << line;
  }
  return s.str();
}

}  // namespace mb
