#include "validate/probe_program.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <exception>
#include <mutex>
#include <thread>

#include "common/model_reference.hpp"
#include "common/reference.hpp"
#include "compile/fp16_emulation.hpp"
#include "compile/shader_cache.hpp"
#include "validate/precision_domain.hpp"
#include "validate/probe_scene_reference.hpp"

namespace mb {
namespace {

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

struct ProbeCacheSetting {
  std::mutex mutex;
  bool set = false;
  std::filesystem::path dir;
};

ProbeCacheSetting& probeCacheSetting() {
  static ProbeCacheSetting s;
  return s;
}

std::atomic<Fp16Mode>& fp16ModeSetting() {
  static std::atomic<Fp16Mode> mode{Fp16Mode::Emulated};
  return mode;
}

void compileInto(ProbeProgram& p) {
  auto t0 = std::chrono::steady_clock::now();
  p.fp16Mode = fp16Mode();
  const bool emulate = p.precision == ShaderPrecision::Fp16 && p.fp16Mode == Fp16Mode::Emulated;
  // fp16 probes skip spirv-opt (spirv-val still runs): SPIRV-Tools v2023.1's constant folding
  // emits 16-bit OpConstants with a 32-bit word count that spirv-val rejects (measured on
  // ue4_metal at fp16), and folding half arithmetic at compile time need not round as half.
  CompileOptions options;
  options.optimization = p.precision == ShaderPrecision::Fp32 ? OptimizationLevel::O2 : OptimizationLevel::O0;
  ShaderCache cache(probeCacheDir());
  CacheIdentity key;
  if (cache.enabled()) {
    key = ShaderCache::identity(ShaderCache::key({ShaderCache::kFormatVersion, MB_VERSION, toolchainVersion(),
                                                  "validate-probe", optimizationCacheToken(options.optimization),
                                                  options.validate ? "validate" : "no-validate", p.shader.glsl}),
                                {p.shader.glsl});
    CompiledArtifacts hit;
    if (cache.load(key, hit) == ShaderCache::Lookup::Hit) {
      p.compiled.spirv = std::move(hit.spirv);
      p.compileCacheHit = true;
    }
  }
  if (!p.compileCacheHit) {
    p.compiled = compileComputeGlsl(p.shader.glsl, p.shader.fileName, options);
    if (cache.enabled()) {
      CompiledArtifacts entry;
      entry.spirv = p.compiled.spirv;
      cache.store(key, entry);  // a failed write only means the next run compiles again
    }
  }
  // The cache holds glslang's half kernel; the emulation pass is cheap and runs every time,
  // once per denormal behaviour (compile/fp16_emulation.hpp).
  if (emulate) {
    const std::vector<uint32_t> half = std::move(p.compiled.spirv);
    p.compiled.spirv = emulateWorstCaseFp16(half, p.shader.fileName, Denormals::Flush);
    p.denormalsKeptSpirv = emulateWorstCaseFp16(half, p.shader.fileName, Denormals::Keep);
  }
  p.compileMs = msSince(t0);
}

[[noreturn]] void missingReference(const std::string& what) {
  throw DiagnosticError({{Severity::Error,
                          "E-NO-REFERENCE",
                          {"shaderlib/manifest.json", 0, 0},
                          what + " has no registered C++ reference",
                          ""}});
}

}  // namespace

void setProbeCacheDir(const std::filesystem::path& dir) {
  ProbeCacheSetting& s = probeCacheSetting();
  std::lock_guard lock(s.mutex);
  s.set = true;
  s.dir = dir;
}

std::filesystem::path probeCacheDir() {
  ProbeCacheSetting& s = probeCacheSetting();
  std::lock_guard lock(s.mutex);
  if (!s.set) {
    s.dir = ShaderCache::defaultDir();
    s.set = true;
  }
  return s.dir;
}

void setFp16Mode(Fp16Mode mode) { fp16ModeSetting() = mode; }
Fp16Mode fp16Mode() { return fp16ModeSetting(); }

std::string ProbeProgram::arithmetic() const {
  if (precision == ShaderPrecision::Fp32) return "fp32";
  return std::string("fp16 ") + fp16ModeName(fp16Mode);
}

Tolerance fp16Tolerance() {
  return {std::numeric_limits<double>::infinity(), 0.0,
          "fp16: error measured and published (docs/fp16.md), not judged; NaN and Inf fail"};
}

ProbeProgram buildBrickProbe(const ShaderLibrary& lib, const Brick& brick, bool unstableVariant,
                             ShaderPrecision precision) {
  ProbeProgram p;
  p.precision = precision;
  p.shader = emitBrickProbe(lib, brick, unstableVariant, precision);
  compileInto(p);
  const ref::Reference* r = ref::Registry::references().find(brick.id);
  if (!r) missingReference("brick '" + brick.id + "'");
  p.reference = r->eval;
  p.tolerance = precision == ShaderPrecision::Fp16 ? fp16Tolerance() : brick.tolerance;
  p.domain.ranges = brick.domain;
  p.domain.geometry = brick.geometry;
  p.domain = domainAtPrecision(lib, p.domain, precision);
  return p;
}

namespace {

// This thread's working copy of `proto` for the closure numbered `id` (a process-unique id, not
// an address that a later closure could reuse), copied when the thread last served another.
ref::ModelEvalInput& workingInput(const ref::ModelEvalInput& proto, uint64_t id) {
  thread_local uint64_t workingId = 0;
  thread_local ref::ModelEvalInput e;
  if (workingId != id) {
    e = proto;
    workingId = id;
  }
  return e;
}

void writeRadiance(const ref::Vec3& r, double* out) {
  out[0] = r.x;
  out[1] = r.y;
  out[2] = r.z;
}

// The by-name closure: every record looks up its scene columns, inputs and bricks by name.
std::function<void(const double*, double*)> byNameReferenceEval(ref::ModelReferenceFn model, const ProbeLayout& layout,
                                                                const MaterialDesc& mat, const ProbeScene& scene,
                                                                std::shared_ptr<const ref::ModelEvalInput> proto,
                                                                uint64_t id) {
  return [model, layout, &mat, scene, proto, id](const double* in, double* out) {
    ref::ModelEvalInput& e = workingInput(*proto, id);
    sceneFromRecord(scene, layout, in, e);
    for (const auto& prm : mat.params) {
      // User parameters are read only by surface code, whose results come fed below.
      if (prm.user || prm.constant) continue;
      const ProbeInput* pi = layout.find(prm.name);
      e.inputs[prm.name].assign(in + pi->offset, in + pi->offset + componentCount(prm.type));
    }
    // With surface code the model inputs are what surface() computed on the GPU; they are
    // passed through unchanged, so NaN or Inf from user code shows in the comparison.
    const double* fed = in + layout.inStride;
    for (const auto& f : layout.fedOutputs) {
      const double* v = fed + (f.offset - componentCount(layout.output));
      e.inputs[f.name].assign(v, v + componentCount(f.type));
      for (int k = 0; k < componentCount(f.type); ++k) out[f.offset + k] = v[k];
    }
    writeRadiance(model(e), out);
  };
}

// One model input a record sets: its index in ref::names::kInputs, where it is read in the
// record (as the closure receives it: inputs, then fed outputs), and where a fed output is
// copied to in `out` (-1: not fed).
struct RecordInput {
  int index = 0;
  uint32_t from = 0;
  int64_t copyTo = -1;
  int size = 0;
};

}  // namespace

std::function<void(const double*, double*)> materialReferenceEval(const Permutation& perm, const ProbeLayout& layout,
                                                                  std::map<std::string, std::string> bricks,
                                                                  bool groundTruths, bool illuminanceInput,
                                                                  ReferenceLookup lookup,
                                                                  std::shared_ptr<const ProbeLtcTable> ltcTable) {
  const MaterialDesc& mat = *perm.material;
  ref::ModelReferenceFn model = ref::ModelRegistry::instance().find(mat.model);
  if (!model) missingReference("model '" + mat.model + "'");
  ProbeScene scene = probeSceneOf(perm, illuminanceInput);
  // What every record shares (bricks, features, constant inputs), built once. A reference
  // evaluation used to build its ModelEvalInput from scratch, maps and strings included: that
  // allocation was the larger part of the reference's time (perf, issue 15). Each thread keeps
  // its own working copy per closure (keyed by a process-unique id, not an address that a
  // later closure could reuse) and overwrites only what a record sets: the scene, which sets
  // the same lights and environment every time, and the non-constant and fed inputs.
  auto proto = std::make_shared<ref::ModelEvalInput>();
  proto->bricks = std::move(bricks);
  proto->groundTruths = groundTruths;
  proto->features.insert(mat.features.begin(), mat.features.end());
  for (const auto& prm : mat.params)
    if (!prm.user && prm.constant) proto->inputs[prm.name] = prm.value;
  if (scene.ltcTableBuffer) {
    if (!ltcTable)
      throw std::logic_error("materialReferenceEval: '" + perm.key() + "' reads the LTC table, none given");
    proto->fetchLtc = [ltcTable](ref::LtcLobe lobe, double NoV, double perceptualRoughness) {
      return ltcTable->texel(lobe, NoV, perceptualRoughness);
    };
  }
  static std::atomic<uint64_t> nextId{1};
  const uint64_t id = nextId++;
  if (lookup == ReferenceLookup::ByName) return byNameReferenceEval(model, layout, mat, scene, proto, id);

  // Resolved: the lookups above, done once here. Inputs no reference reads (index -1) are
  // skipped; the by-name path stores them in a map nothing reads.
  proto->resolve();
  const SceneColumns columns = sceneColumns(scene, layout);
  std::vector<RecordInput> recordInputs;
  for (const auto& prm : mat.params) {
    if (prm.user || prm.constant) continue;
    const int index = ref::names::find(ref::names::kInputs, prm.name);
    if (index < 0) continue;
    const ProbeInput* pi = layout.find(prm.name);
    recordInputs.push_back({index, pi->offset, -1, componentCount(prm.type)});
  }
  for (const auto& f : layout.fedOutputs) {
    const uint32_t from = layout.inStride + (f.offset - componentCount(layout.output));
    recordInputs.push_back({ref::names::find(ref::names::kInputs, f.name), from, f.offset, componentCount(f.type)});
  }
  return [model, scene, columns, recordInputs, proto, id](const double* in, double* out) {
    ref::ModelEvalInput& e = workingInput(*proto, id);
    sceneFromRecord(scene, columns, in, e);
    for (const RecordInput& r : recordInputs) {
      if (r.index >= 0) e.setInput(r.index, in + r.from, r.size);
      // Fed outputs pass through unchanged, so NaN or Inf from user code shows.
      if (r.copyTo >= 0)
        for (int k = 0; k < r.size; ++k) out[r.copyTo + k] = in[r.from + k];
    }
    writeRadiance(model(e), out);
  };
}

Tolerance compositionTolerance(const ShaderLibrary& lib, const Permutation& perm,
                               const std::vector<std::string>& bricks, double radianceBound) {
  // First-order propagation: relative errors of the bricks multiplied together add up, and
  // a sum of lobes is no worse than its worst lobe; 1e-5 covers the composition's own fp32
  // arithmetic (a few dozen operations at ~6e-8 each).
  std::map<std::string, double> scales;
  const ShadingModel* model = lib.findModel(perm.material->model);
  for (const auto& [role, brick] : boundRoles(lib, perm)) {
    const ModelRole* r = model ? model->findRole(role) : nullptr;
    if (r && r->toleranceScale > 1.0) scales[brick] = std::max(scales[brick], r->toleranceScale);
  }
  Tolerance t;
  t.rel = 1e-5;
  t.abs = 0.0;
  for (const auto& id : bricks) {
    const Brick* b = lib.findBrick(id);
    auto scale = scales.find(id);
    t.rel += b->tolerance.rel;
    t.abs += b->tolerance.abs * (scale == scales.end() ? 1.0 : scale->second);
  }
  t.reason = "sum of the bound bricks' tolerances plus 1e-5 for the composition";
  if (!scales.empty()) t.reason += ", the absolute ones times their roles' toleranceScale";
  // The result is linear in the lights' illuminance and the environment's radiance, and so is
  // its absolute error.
  t.abs *= radianceBound;
  return t;
}

ProbeProgram buildPermutationProbe(const ShaderLibrary& lib, const Permutation& perm, bool illuminanceInput) {
  ProbeProgram p = describePermutationProbe(lib, perm, illuminanceInput);
  compileInto(p);
  return p;
}

ProbeProgram describePermutationProbe(const ShaderLibrary& lib, const Permutation& perm, bool illuminanceInput) {
  const MaterialDesc& mat = *perm.material;
  ProbeProgram p;
  p.precision = precisionOf(perm);
  p.shader = emitPermutation(lib, perm, illuminanceInput);

  p.tolerance = compositionTolerance(lib, perm, p.shader.bricks, probeSceneRadianceBound(probeSceneOf(perm, false)));
  if (illuminanceInput) {
    p.tolerance.abs *= kIlluminanceRange.hi;
    p.tolerance.reason += "; abs scaled by the largest illuminance";
    // fp16 shading takes pre-exposed light (Filament's pre-exposure), from the smallest
    // normal half to 2^10: near 65504 the ~0.1% half rounding of a radiance that just fits
    // would round to Inf.
    p.domain.ranges["illuminance"] = p.precision == ShaderPrecision::Fp16 ? kIlluminanceRangeFp16 : kIlluminanceRange;
  }
  if (p.precision == ShaderPrecision::Fp16) p.tolerance = fp16Tolerance();

  for (const auto& in : probeSceneInputs(probeSceneOf(perm, illuminanceInput)))
    if (in.name != "illuminance") p.domain.ranges[in.name] = in.range;
  for (const auto& prm : mat.params)
    if (!prm.constant) p.domain.ranges[prm.name] = prm.range;
  p.domain = domainAtPrecision(lib, p.domain, p.precision);
  std::map<std::string, std::string> bricks;
  for (const auto& [role, id] : boundRoles(lib, perm)) bricks[role] = id;
  if (p.shader.readsTable) p.ltcTable = probeLtcTable(lib);

  p.reference = materialReferenceEval(perm, p.shader.layout, bricks, false, illuminanceInput, ReferenceLookup::Resolved,
                                      p.ltcTable);
  return p;
}

ProbeRun runProbeOnGpu(harness::VulkanHarness& gpu, const ProbeProgram& program, std::vector<float> inputs) {
  const ProbeLayout& layout = program.shader.layout;
  ProbeRun run;
  run.count = layout.inStride ? inputs.size() / layout.inStride : 0;
  // An emulated fp16 kernel is fp32 SPIR-V: only the driver's own half arithmetic needs the
  // feature.
  if (program.precision == ShaderPrecision::Fp16 && program.fp16Mode == Fp16Mode::Driver &&
      !gpu.supportsShaderFloat16()) {
    throw harness::HarnessError("device \"" + gpu.deviceName() + "\" does not support shaderFloat16 " +
                                "(VK_KHR_shader_float16_int8); fp16 probes cannot run on it");
  }
  auto kernel = gpu.kernelFor(program.compiled.spirv, program.shader.readsTable);
  auto result = gpu.run(*kernel, inputs, layout.inStride, layout.outStride, run.count, {}, program.tableBuffer());
  run.gpu = std::move(result.outputs);
  run.gpuMs = result.gpuMs;
  run.firstDispatchMs = result.firstDispatchMs;
  if (program.precision == ShaderPrecision::Fp16 && program.fp16Mode == Fp16Mode::Emulated &&
      !program.denormalsKeptSpirv.empty()) {
    // The emulated fp16 kernel under the other denormal behaviour: a value is NaN (Inf) when
    // either behaviour gives NaN (Inf), as some conforming device computes it that way;
    // otherwise the flushing kernel's value is kept.
    auto kept = gpu.run(*gpu.kernelFor(program.denormalsKeptSpirv, program.shader.readsTable), inputs, layout.inStride,
                        layout.outStride, run.count, {}, program.tableBuffer());
    for (size_t k = 0; k < run.gpu.size(); ++k) {
      float& v = run.gpu[k];
      const float w = kept.outputs[k];
      if (std::isnan(w) || (std::isinf(w) && !std::isnan(v))) v = w;
    }
    run.gpuMs += kept.gpuMs;
    run.firstDispatchMs += kept.firstDispatchMs;
  }
  run.inputs = std::move(inputs);
  return run;
}

namespace {

// One thread's buffers for the reference of one record.
struct RecordEvaluator {
  const ProbeProgram& program;
  const std::vector<uint32_t>& directionColumns;
  ProbeRun& run;
  std::vector<double> record, perturbed, moved;

  RecordEvaluator(const ProbeProgram& p, const std::vector<uint32_t>& cols, ProbeRun& r)
      : program(p), directionColumns(cols), run(r) {
    const ProbeLayout& layout = p.shader.layout;
    record.resize(layout.inStride + layout.fedCount());
    perturbed.resize(record.size());
    moved.resize(layout.outStride);
  }

  // The record as the reference reads it: the inputs, then the fed outputs (surface values
  // the GPU computed).
  void load(uint64_t i) {
    const ProbeLayout& layout = program.shader.layout;
    const uint32_t fed = layout.fedCount(), fedFrom = layout.outStride - fed;
    for (uint32_t k = 0; k < layout.inStride; ++k) record[k] = run.inputs[i * layout.inStride + k];
    for (uint32_t k = 0; k < fed; ++k) record[layout.inStride + k] = run.gpu[i * layout.outStride + fedFrom + k];
  }

  void reference(uint64_t i) {
    load(i);
    program.reference(record.data(), run.reference.data() + i * program.shader.layout.outStride);
  }

  // kConditioningPatterns fixed sign patterns on the vector components (direction error),
  // in opposite pairs, so that runs are reproducible; each with a skew of the normalized
  // lengths (the half vector's error near v = -l; ref::ScopedHalfVectorSumSkew). The
  // allowance is the largest move: an estimate of the worst case over the 2-ulp ball.
  // Expects record i loaded and its reference computed.
  void conditioning(uint64_t i) {
    const uint32_t stride = program.shader.layout.outStride;
    const double* ref = run.reference.data() + i * stride;
    const double eps = kDirectionInputUlps * 0x1p-23;
    for (uint32_t pattern = 0; pattern < kConditioningPatterns; ++pattern) {
      double sign = pattern % 2 ? -1.0 : 1.0;
      perturbed = record;
      for (size_t c = 0; c < directionColumns.size(); ++c) {
        uint32_t bit = (static_cast<uint32_t>(c + 1) * 0x9E3779B9u >> (7 + pattern / 2)) & 1u;
        perturbed[directionColumns[c]] *= 1.0 + (bit ? sign : -sign) * eps;
      }
      ref::ScopedHalfVectorSumSkew skew(sign * eps);  // thread_local: each thread its own
      program.reference(perturbed.data(), moved.data());
      for (uint32_t k = 0; k < stride; ++k) {
        double d = std::abs(moved[k] - ref[k]);
        if (std::isfinite(d)) {
          double& c = run.conditioning[i * stride + k];
          c = std::max(c, d);
        }
      }
    }
  }
};

// |gpu - ref| / bound of one value as ErrorStats::add takes it for its worst record, with
// `allowance` added to the arithmetic bound; -1 for values it does not rank (non-finite).
double errorRatio(float gpu, double ref, const Tolerance& tol, double allowance) {
  if (!std::isfinite(ref) || !std::isfinite(gpu)) return -1;
  const double err = std::abs(static_cast<double>(gpu) - ref);
  const double allowed = tol.abs + tol.rel * std::abs(ref) + allowance;
  return allowed > 0 ? err / allowed : (err > 0 ? std::numeric_limits<double>::max() : 0.0);
}

// Largest errorRatio over record i's values.
double recordRatio(const ProbeRun& run, const ProbeProgram& program, uint64_t i, bool withAllowance) {
  const uint32_t stride = program.shader.layout.outStride;
  double r = -1;
  for (uint32_t k = 0; k < stride; ++k) {
    const size_t at = i * stride + k;
    r = std::max(
        r, errorRatio(run.gpu[at], run.reference[at], program.tolerance, withAllowance ? run.conditioning[at] : 0.0));
  }
  return r;
}

// Records [begin, end): the reference, and the allowance where options ask for it. Sets
// conditioned[i] for the records whose allowance was computed.
void referenceRecords(ProbeRun& run, const ProbeProgram& program, const ReferenceOptions& options,
                      const std::vector<uint32_t>& directionColumns, std::vector<char>& conditioned, uint64_t begin,
                      uint64_t end) {
  RecordEvaluator eval(program, directionColumns, run);
  for (uint64_t i = begin; i < end; ++i) {
    eval.reference(i);
    if (directionColumns.empty()) continue;
    // Outside abs + rel * |ref| somewhere (NaN, Inf and an invalid reference are judged
    // without the allowance, so they do not count).
    if (options.onlyWhereNeeded && recordRatio(run, program, i, false) <= 1.0) continue;
    eval.conditioning(i);
    conditioned[i] = 1;
  }
}

// onlyWhereNeeded keeps every verdict by construction, but ErrorStats also names the worst
// record (largest error / bound, allowance included), which validate reports as worst_input.
// A record without its allowance has a ratio at least as large as with it, so, taking the
// records in decreasing order of that upper bound, the allowance is computed until the bound
// falls below the best ratio already known: the worst record, and its ratio, are then exactly
// those of the full computation, usually for a few more records.
void conditionWorstCandidates(ProbeRun& run, const ProbeProgram& program, const std::vector<uint32_t>& directionColumns,
                              std::vector<char>& conditioned) {
  // The full computation's worst: the largest ratio, the earliest record among equals.
  double best = -1;
  uint64_t bestRecord = 0;
  auto offer = [&](double ratio, uint64_t i) {
    if (ratio > best || (ratio == best && i < bestRecord)) {
      best = ratio;
      bestRecord = i;
    }
  };
  std::vector<std::pair<double, uint64_t>> candidates;
  for (uint64_t i = 0; i < run.count; ++i) {
    if (conditioned[i]) {
      offer(recordRatio(run, program, i, true), i);
    } else {
      candidates.push_back({recordRatio(run, program, i, false), i});
    }
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
  RecordEvaluator eval(program, directionColumns, run);
  for (const auto& [upper, i] : candidates) {
    if (upper < best || upper < 0) break;
    if (upper == best && i > bestRecord) continue;  // cannot win: equal at most, and later
    eval.load(i);
    eval.conditioning(i);
    conditioned[i] = 1;
    offer(recordRatio(run, program, i, true), i);
  }
}

}  // namespace

void computeReference(ProbeRun& run, const ProbeProgram& program, const ReferenceOptions& options) {
  const ProbeLayout& layout = program.shader.layout;
  run.reference.assign(run.count * layout.outStride, 0.0);
  run.conditioning.assign(run.count * layout.outStride, 0.0);
  const std::vector<uint32_t> directionColumns =
      options.conditioning ? directionInputColumns(layout) : std::vector<uint32_t>{};
  std::vector<char> conditioned(run.count, 0);  // char, not bool: threads write neighbours
  unsigned threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  // Below ~256 records per thread the thread start costs more than it saves.
  threads = static_cast<unsigned>(std::min<uint64_t>(threads, std::max<uint64_t>(1, run.count / 256)));
  if (threads <= 1) {
    referenceRecords(run, program, options, directionColumns, conditioned, 0, run.count);
  } else {
    std::vector<std::thread> pool;
    std::vector<std::exception_ptr> errors(threads);
    for (unsigned t = 0; t < threads; ++t) {
      const uint64_t begin = run.count * t / threads, end = run.count * (t + 1) / threads;
      pool.emplace_back([&, t, begin, end] {
        try {
          referenceRecords(run, program, options, directionColumns, conditioned, begin, end);
        } catch (...) {
          errors[t] = std::current_exception();  // rethrown on the caller's thread
        }
      });
    }
    for (auto& th : pool) th.join();
    for (auto& e : errors)
      if (e) std::rethrow_exception(e);
  }
  if (options.onlyWhereNeeded && !directionColumns.empty())
    conditionWorstCandidates(run, program, directionColumns, conditioned);
}

ProbeRun runProbe(harness::VulkanHarness& gpu, const ProbeProgram& program, std::vector<float> inputs,
                  const ReferenceOptions& options) {
  ProbeRun run = runProbeOnGpu(gpu, program, std::move(inputs));
  computeReference(run, program, options);
  return run;
}

ProbeRun runProbe(harness::VulkanHarness& gpu, const ProbeProgram& program, std::vector<float> inputs,
                  bool conditioning) {
  ReferenceOptions options;
  options.conditioning = conditioning;
  return runProbe(gpu, program, std::move(inputs), options);
}

std::vector<uint32_t> directionInputColumns(const ProbeLayout& layout) {
  std::vector<uint32_t> cols;
  for (const char* name : {"n", "v", "l"})
    if (const ProbeInput* in = layout.find(name); in && in->type == ValueType::Vec3)
      for (uint32_t k = 0; k < 3; ++k) cols.push_back(in->offset + k);
  return cols;
}

void addErrors(ErrorStats& s, const ProbeRun& run, const ProbeProgram& program, uint64_t firstRecord) {
  const ProbeLayout& layout = program.shader.layout;
  uint32_t stride = layout.outStride;
  // A record is the shaded output first, then the surface outputs fed to the model
  // (ProbeLayout::fedOutputs): normals and other signed values that are not radiance.
  const uint32_t outputComponents = static_cast<uint32_t>(componentCount(layout.output));
  for (uint64_t i = 0; i < run.count; ++i)
    for (uint32_t k = 0; k < stride; ++k)
      s.add(static_cast<int64_t>(firstRecord + i), run.gpu[i * stride + k], run.reference[i * stride + k],
            program.tolerance, run.conditioning.empty() ? 0.0 : run.conditioning[i * stride + k], k < outputComponents);
}

ErrorStats compare(const ProbeRun& run, const ProbeProgram& program) {
  ErrorStats s;
  addErrors(s, run, program, 0);
  return s;
}

}  // namespace mb
