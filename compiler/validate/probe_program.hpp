// A probe ready to run on the harness and to compare: the emitted shader, its SPIR-V, the
// reference that evaluates one record in double, and the domain and tolerance to use.
// validate, eval (and later stress and bench) all build probes here; none has its own way
// to build shaders.
#pragma once
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "compile/glsl_compiler.hpp"
#include "emit/emitter.hpp"
#include "harness/vulkan_harness.hpp"
#include "validate/error_metrics.hpp"
#include "validate/probe_ltc_table.hpp"
#include "validate/sampler.hpp"

namespace mb {

struct ProbeProgram {
  EmittedShader shader;
  CompileResult compiled;
  double compileMs = 0;
  bool compileCacheHit = false;  // the SPIR-V came from the probe cache (setProbeCacheDir)
  std::function<void(const double* in, double* out)> reference;
  Tolerance tolerance;
  SampleDomain domain;
  ShaderPrecision precision = ShaderPrecision::Fp32;
  // How an fp16 kernel computes. Emulated: `compiled` is emulateWorstCaseFp16's kernel with
  // denormals flushed and `denormalsKeptSpirv` the one with denormals kept; runProbeOnGpu
  // runs both and reports a value as NaN/Inf when either gives NaN/Inf.
  Fp16Mode fp16Mode = Fp16Mode::Emulated;
  std::vector<uint32_t> denormalsKeptSpirv;
  // "fp16 emulated", "fp16 driver" or "fp32", for reports.
  std::string arithmetic() const;
  // The LTC table the kernel reads (shader.readsTable) and the reference looks up.
  std::shared_ptr<const ProbeLtcTable> ltcTable;
  // The table buffer to give the kernel's run: ltcTable's texels, or null.
  const std::vector<float>* tableBuffer() const { return ltcTable ? &ltcTable->texels : nullptr; }
};

// Probes' SPIR-V is kept in the content-addressed ShaderCache (compile/shader_cache.hpp) under
// a key of the emitted GLSL (which holds every brick's source verbatim), the compile options,
// matbricks' and the toolchain's versions: glslang + spirv-opt is ~25 ms of one core per
// probe, more than the rest of a warm validation. Default: ShaderCache::defaultDir(); an empty
// path turns it off. Process-wide; set it before building probes.
void setProbeCacheDir(const std::filesystem::path& dir);
std::filesystem::path probeCacheDir();

// How fp16 probes built from now on compute (default Fp16Mode::Emulated). Process-wide, like
// the probe cache: the CLI sets it from --fp16 before building probes.
void setFp16Mode(Fp16Mode mode);
Fp16Mode fp16Mode();

// `unstableVariant`: probe the brick's naive form against the same reference and tolerance.
// At fp16 the domain is the fp16 domain (precision_domain.hpp) and the tolerance is
// fp16Tolerance(): the error is measured and published, only NaN/Inf fail.
ProbeProgram buildBrickProbe(const ShaderLibrary& lib, const Brick& brick, bool unstableVariant = false,
                             ShaderPrecision precision = ShaderPrecision::Fp32);
// The precision is the permutation's own axis (Permutation::precision).
// `illuminanceInput`: the probe takes the light's illuminance as an input column
// (emitPermutation); its domain is kIlluminanceRange, and the absolute tolerance scales with
// the largest illuminance (the result is linear in it).
ProbeProgram buildPermutationProbe(const ShaderLibrary& lib, const Permutation& perm, bool illuminanceInput = false);
// The same without compiling (`compiled` empty): the layout, domain, tolerance and reference,
// for work that runs the reference alone.
ProbeProgram describePermutationProbe(const ShaderLibrary& lib, const Permutation& perm, bool illuminanceInput = false);
// A permutation's fp32 tolerance: the sum of its bricks' tolerances plus 1e-5 relative for the
// composition, the absolute part scaled by `radianceBound` (the scene's largest illuminance or
// radiance input: a unit-illuminance composition's absolute error scales with it). validate
// uses the probe scene's bound, preview its own scene's. A brick bound to a role with a
// toleranceScale (ModelRole) has its absolute part scaled by that factor as well.
Tolerance compositionTolerance(const ShaderLibrary& lib, const Permutation& perm,
                               const std::vector<std::string>& bricks, double radianceBound);
// Illuminance (lux-like units) from starlight to well above direct sunlight.
inline constexpr Range kIlluminanceRange{1e-6, 1e6};
// At fp16: pre-exposed illuminance, from the smallest normal half (2^-14) to 2^10.
inline constexpr Range kIlluminanceRangeFp16{0x1p-14, 1024.0};

// The manifest tolerances are fp32 error analyses; half precision has no per-brick bound
// yet. At fp16 errors are reported (docs/fp16.md), not judged: abs is infinite, so a value
// fails only as NaN or Inf.
Tolerance fp16Tolerance();

struct ProbeRun {
  std::vector<float> inputs;      // count * inStride
  std::vector<float> gpu;         // count * outStride
  std::vector<double> reference;  // count * outStride
  // Per output value: how far the reference moves when the direction vectors n, v, l are
  // perturbed by kDirectionInputUlps fp32 ulps (see inputConditioning). Zero for probes
  // without vector geometry.
  std::vector<double> conditioning;  // count * outStride
  double gpuMs = 0;
  // Wall time of the kernel's first dispatch (lavapipe's JIT compile), 0 when the kernel had
  // run before (harness::RunResult::firstDispatchMs).
  double firstDispatchMs = 0;
  uint64_t count = 0;
};

// How the CPU half of a probe run is done. Every choice gives the same verdicts.
struct ReferenceOptions {
  // Fill ProbeRun::conditioning at all; callers that never judge against a tolerance (stress)
  // skip it.
  bool conditioning = true;
  // Only for values that the arithmetic tolerance alone does not pass: |gpu - ref| >
  // abs + rel * |ref| with both finite. The allowance only ever widens the bound, so a value
  // inside it passes with any allowance, and a value outside gets exactly the allowance the
  // full computation gives it: the same failures and the same passed_by_conditioning, at a
  // ninth of the reference evaluations (kConditioningPatterns extra ones per record are
  // then spent on a handful of values). Elsewhere conditioning stays 0, so callers that use
  // the allowance of every value (pruned-equals-full, energy) leave this off.
  bool onlyWhereNeeded = false;
  // Reference threads; 0: std::thread::hardware_concurrency(). Records are independent and
  // each is evaluated whole by one thread, so the results do not depend on it.
  unsigned threads = 0;
};

// The backward error of fp32 shading geometry: normalize, the v + l sum and inversesqrt
// each round the direction vectors by about one ulp, so an fp32 shader evaluates its brick at
// directions up to ~2 ulps (2^-22 relative per component) away from the exact ones. Where
// the problem itself is ill-conditioned (the half vector of nearly opposite v and l, whose
// direction error grows as 1e-7 / |v + l|), no fp32 formulation can do better than this.
inline constexpr double kDirectionInputUlps = 2.0;
// Sign patterns tried per record (in opposite pairs).
inline constexpr uint32_t kConditioningPatterns = 8;

// Runs the probe on the GPU and the reference on the CPU over the same fp32 inputs.
// `conditioning`: also fill ProbeRun::conditioning (kConditioningPatterns extra reference
// evaluations per record); callers that never judge against a tolerance (stress) skip it.
ProbeRun runProbe(harness::VulkanHarness& gpu, const ProbeProgram& program, std::vector<float> inputs,
                  bool conditioning = true);
ProbeRun runProbe(harness::VulkanHarness& gpu, const ProbeProgram& program, std::vector<float> inputs,
                  const ReferenceOptions& options);
// The two halves of runProbe. runProbeOnGpu fills inputs, gpu, gpuMs and firstDispatchMs;
// computeReference fills reference and conditioning from them.
ProbeRun runProbeOnGpu(harness::VulkanHarness& gpu, const ProbeProgram& program, std::vector<float> inputs);
void computeReference(ProbeRun& run, const ProbeProgram& program, const ReferenceOptions& options);
ErrorStats compare(const ProbeRun& run, const ProbeProgram& program);
// Adds a run's errors to `s`, its records numbered from `firstRecord`: one run of many records
// judged in parts (eval streams its rows in chunks) gives the same statistics as one compare.
void addErrors(ErrorStats& s, const ProbeRun& run, const ProbeProgram& program, uint64_t firstRecord);
// The double reference of a permutation's probe: the model's reference composition with the
// given role -> brick binding, reading the scene (frame, lights, environment; see
// probe_scene_reference.hpp) and the non-constant parameters from a record laid out as
// `layout`. With `groundTruths`, each bound brick that has a ground truth is evaluated by it
// (bench's yardstick). The permutation's material must outlive the result.
// `lookup`: Resolved finds each role's reference, each input's column and the scene's columns
// once, when the closure is built, so that a record costs no name lookup and no allocation;
// ByName looks every name up per record and brick call (the path the resolved one is tested
// against: both give the same doubles). `ltcTable`: the table the probe's rectangle and disk
// lights read (ProbeProgram::ltcTable); required when the permutation has them.
enum class ReferenceLookup { Resolved, ByName };
std::function<void(const double*, double*)> materialReferenceEval(
    const Permutation& perm, const ProbeLayout& layout, std::map<std::string, std::string> bricks,
    bool groundTruths = false, bool illuminanceInput = false, ReferenceLookup lookup = ReferenceLookup::Resolved,
    std::shared_ptr<const ProbeLtcTable> ltcTable = nullptr);
// Record columns holding the direction vectors n, v, l (empty if the probe has none).
std::vector<uint32_t> directionInputColumns(const ProbeLayout& layout);

}  // namespace mb
