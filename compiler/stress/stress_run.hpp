// `matbricks stress`: runs one probe (a brick or a permutation) over the adversarial input
// set (stress_inputs.hpp) and summarizes in-domain and out-of-domain results separately.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "validate/probe_program.hpp"

namespace mb {

// Summary of the GPU values of one class of records (in or out of the domain).
struct StressStats {
  uint64_t records = 0;
  uint64_t values = 0;
  uint64_t nanCount = 0;
  uint64_t infCount = 0;
  uint64_t negativeCount = 0;
  // Values whose double reference is itself NaN/Inf: the input has no defined result (for
  // example a tangent parallel to the normal); reported, never judged.
  uint64_t referenceUndefined = 0;
  // Inf where the exact result is itself beyond the largest finite value of the precision
  // (65504 in half): IEEE rounding of that value is Inf, so no formulation can do better.
  // Reported, never judged; an Inf whose exact result is in range counts in infCount.
  uint64_t overflowCount = 0;
  double maxFinite = 3.4028234663852886e38;  // of the probe's precision
  double maxAbs = 0;
  double maxRel = 0;  // |gpu - ref| / max(|ref|, kRelativeErrorFloor), over finite values
  // The record to replay: the first NaN/Inf if any, else the largest relative error.
  int64_t worstRecord = -1;
  bool worstIsNonFinite = false;
  void add(int64_t record, float gpu, double ref);
};

struct StressResult {
  std::string key;           // "brick.d_ggx", "brick.d_ggx.fp16", or a permutation key
  std::string kind;          // "brick" or "permutation"
  std::string id;            // brick id, or the material file (for the replay command)
  std::string materialName;  // the material within that file (a glTF file holds several)
  ShaderPrecision precision = ShaderPrecision::Fp32;
  Fp16Mode fp16Mode = Fp16Mode::Emulated;  // how an fp16 probe computed (ProbeProgram::fp16Mode)
  std::string compileError;                // set when the probe did not build at this precision
  StressStats inDomain, outOfDomain;
  std::vector<std::string> columns;
  std::vector<float> worstInDomainRow, worstOutOfDomainRow;  // empty if none
  std::vector<double> worstInDomainGpu, worstInDomainReference;
  // Fails on in-domain NaN/Inf, or when the probe cannot be built.
  bool passed() const { return compileError.empty() && inDomain.nanCount == 0 && inDomain.infCount == 0; }
};

struct StressOptions {
  uint64_t randomSamples = 1024;  // validation-sampler records added to the adversarial set
  uint64_t seed = 1;
};

StressResult stressProbe(harness::VulkanHarness& gpu, const ProbeProgram& program, const std::string& kind,
                         const std::string& id, const StressOptions& options);

// "h1,h2,...\nv1,v2,...\n": a CSV that `matbricks eval` reads (values round-trip fp32).
std::string csvRow(const std::vector<std::string>& columns, const std::vector<float>& row);

}  // namespace mb
