// validate: run a probe over seeded samples and judge it against its tolerance.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "validate/probe_program.hpp"

namespace mb {

inline ReferenceOptions validationOptions() {
  ReferenceOptions o;
  o.onlyWhereNeeded = true;
  return o;
}

struct ValidationRecord {
  std::string key;
  std::string kind;  // "brick" or "permutation"
  uint64_t samples = 0;
  ErrorStats stats;
  Tolerance tolerance;
  double compileMs = 0;
  bool compileCached = false;  // SPIR-V from the probe cache (setProbeCacheDir)
  double gpuMs = 0;
  double firstDispatchMs = 0;  // the pipeline's first dispatch (lavapipe's JIT); see ProbeRun
  double referenceMs = 0;      // double reference, input-conditioning allowance and comparison
  size_t spirvInstructions = 0;
  std::string worstInput;  // "col=value,..." of the worst record, replayable with eval
  // A permutation's shaded output is radiance, which is never negative: a negative GPU value
  // fails it even where the reference agrees (a fit below 0 in both). The surface outputs its
  // probe also returns (a clear-coat normal) are signed and not counted (addErrors). Bricks are
  // not judged on sign: many return signed values (SH, bent normals, Fresnel-weighted terms).
  bool judgesNegatives() const { return kind == "permutation"; }
  bool passed() const { return stats.passed() && !(judgesNegatives() && stats.negativeCount > 0); }
};

// `options`: how the reference is computed; the default (the allowance only where it is
// needed, all cores) gives the verdict and error statistics of the full computation, except
// that max_conditioning_allowance is then the largest allowance among the values that needed
// one (ReferenceOptions::onlyWhereNeeded).
ValidationRecord validateProbe(harness::VulkanHarness& gpu, const ProbeProgram& program, const std::string& kind,
                               uint64_t samples, uint64_t seed, const ReferenceOptions& options = validationOptions());

nlohmann::json toJson(const ValidationRecord& r);
// Fixed-width table, one row per record, for people.
std::string formatValidationTable(const std::vector<ValidationRecord>& records);

}  // namespace mb
