// validate: run a probe over seeded samples and judge it against its tolerance.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "validate/probe_program.hpp"

namespace mb {

struct ValidationRecord {
  std::string key;
  std::string kind;  // "brick" or "permutation"
  uint64_t samples = 0;
  ErrorStats stats;
  Tolerance tolerance;
  double compileMs = 0;
  double gpuMs = 0;
  size_t spirvInstructions = 0;
  std::string worstInput;  // "col=value,..." of the worst record, replayable with eval
  // A permutation's outputs are radiance, which is never negative: a negative GPU value fails
  // it even where the reference agrees (a fit below 0 in both, issue 18). Bricks are not
  // judged on sign: many return signed values (SH, bent normals, Fresnel-weighted terms).
  bool judgesNegatives() const { return kind == "permutation"; }
  bool passed() const { return stats.passed() && !(judgesNegatives() && stats.negativeCount > 0); }
};

ValidationRecord validateProbe(harness::VulkanHarness& gpu, const ProbeProgram& program, const std::string& kind,
                               uint64_t samples, uint64_t seed);

nlohmann::json toJson(const ValidationRecord& r);
// Fixed-width table, one row per record, for people.
std::string formatValidationTable(const std::vector<ValidationRecord>& records);

}  // namespace mb
