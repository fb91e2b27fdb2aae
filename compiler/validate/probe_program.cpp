#include "validate/probe_program.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "common/model_reference.hpp"
#include "common/reference.hpp"
#include "validate/precision_domain.hpp"
#include "validate/probe_scene_reference.hpp"

namespace mb {
namespace {

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void compileInto(ProbeProgram& p) {
  auto t0 = std::chrono::steady_clock::now();
  // fp16 probes skip spirv-opt (spirv-val still runs): SPIRV-Tools v2023.1's constant folding
  // emits 16-bit OpConstants with a 32-bit word count that spirv-val rejects (measured on
  // ue4_metal at fp16), and folding half arithmetic at compile time need not round as half.
  CompileOptions options;
  options.optimize = p.precision == ShaderPrecision::Fp32;
  p.compiled = compileComputeGlsl(p.shader.glsl, p.shader.fileName, options);
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
  p.domain = domainAtPrecision(p.domain, precision);
  return p;
}

std::function<void(const double*, double*)> materialReferenceEval(const Permutation& perm, const ProbeLayout& layout,
                                                                  std::map<std::string, std::string> bricks,
                                                                  bool groundTruths, bool illuminanceInput) {
  const MaterialDesc& mat = *perm.material;
  ref::ModelReferenceFn model = ref::ModelRegistry::instance().find(mat.model);
  if (!model) missingReference("model '" + mat.model + "'");
  ProbeScene scene = probeSceneOf(perm, illuminanceInput);
  return [model, layout, &mat, scene, bricks = std::move(bricks), groundTruths](const double* in, double* out) {
    ref::ModelEvalInput e;
    sceneFromRecord(scene, layout, in, e);
    e.bricks = bricks;
    e.groundTruths = groundTruths;
    e.features.insert(mat.features.begin(), mat.features.end());
    for (const auto& prm : mat.params) {
      if (prm.user) continue;  // read only by surface code, whose results come fed below
      if (prm.constant) {
        e.inputs[prm.name] = prm.value;
      } else {
        const ProbeInput* pi = layout.find(prm.name);
        e.inputs[prm.name].assign(in + pi->offset, in + pi->offset + componentCount(prm.type));
      }
    }
    // With surface code the model inputs are what surface() computed on the GPU; they are
    // passed through unchanged, so NaN or Inf from user code shows in the comparison.
    const double* fed = in + layout.inStride;
    for (const auto& f : layout.fedOutputs) {
      const double* v = fed + (f.offset - componentCount(layout.output));
      e.inputs[f.name].assign(v, v + componentCount(f.type));
      for (int k = 0; k < componentCount(f.type); ++k) out[f.offset + k] = v[k];
    }
    ref::Vec3 r = model(e);
    out[0] = r.x;
    out[1] = r.y;
    out[2] = r.z;
  };
}

ProbeProgram buildPermutationProbe(const ShaderLibrary& lib, const Permutation& perm, bool illuminanceInput) {
  const MaterialDesc& mat = *perm.material;
  ProbeProgram p;
  p.precision = precisionOf(perm);
  p.shader = emitPermutation(lib, perm, illuminanceInput);
  compileInto(p);

  // First-order propagation: relative errors of the bricks multiplied together add up, and
  // a sum of lobes is no worse than its worst lobe; 1e-5 covers the composition's own fp32
  // arithmetic (a few dozen operations at ~6e-8 each).
  p.tolerance.rel = 1e-5;
  p.tolerance.abs = 0.0;
  for (const auto& id : p.shader.bricks) {
    const Brick* b = lib.findBrick(id);
    p.tolerance.rel += b->tolerance.rel;
    p.tolerance.abs += b->tolerance.abs;
  }
  p.tolerance.reason = "sum of the bound bricks' tolerances plus 1e-5 for the composition";
  // The result is linear in the lights' illuminance and the environment's radiance, and so is
  // its absolute error.
  p.tolerance.abs *= probeSceneRadianceBound(probeSceneOf(perm, false));
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
  p.domain = domainAtPrecision(p.domain, p.precision);
  std::map<std::string, std::string> bricks;
  for (const auto& [role, id] : boundRoles(lib, perm)) bricks[role] = id;

  p.reference = materialReferenceEval(perm, p.shader.layout, bricks, false, illuminanceInput);
  return p;
}

ProbeRun runProbe(harness::VulkanHarness& gpu, const ProbeProgram& program, std::vector<float> inputs,
                  bool conditioning) {
  const ProbeLayout& layout = program.shader.layout;
  ProbeRun run;
  run.count = layout.inStride ? inputs.size() / layout.inStride : 0;
  if (program.precision == ShaderPrecision::Fp16 && !gpu.supportsShaderFloat16()) {
    throw harness::HarnessError("device \"" + gpu.deviceName() + "\" does not support shaderFloat16 " +
                                "(VK_KHR_shader_float16_int8); fp16 probes cannot run on it");
  }
  auto kernel = gpu.createKernel(program.compiled.spirv);
  auto result = gpu.run(*kernel, inputs, layout.inStride, layout.outStride, run.count);
  run.gpu = std::move(result.outputs);
  run.gpuMs = result.gpuMs;

  run.reference.resize(run.count * layout.outStride);
  run.conditioning.assign(run.count * layout.outStride, 0.0);
  std::vector<uint32_t> directionColumns = conditioning ? directionInputColumns(layout) : std::vector<uint32_t>{};
  // Fed outputs (surface values the GPU computed) follow the inputs in the reference's record.
  const uint32_t fed = layout.fedCount(), fedFrom = layout.outStride - fed;
  std::vector<double> record(layout.inStride + fed), perturbed(layout.inStride + fed), moved(layout.outStride);
  for (uint64_t i = 0; i < run.count; ++i) {
    for (uint32_t k = 0; k < layout.inStride; ++k) record[k] = inputs[i * layout.inStride + k];
    for (uint32_t k = 0; k < fed; ++k) record[layout.inStride + k] = run.gpu[i * layout.outStride + fedFrom + k];
    double* ref = run.reference.data() + i * layout.outStride;
    program.reference(record.data(), ref);
    if (directionColumns.empty()) continue;
    // kConditioningPatterns fixed sign patterns on the vector components (direction error),
    // in opposite pairs, so that runs are reproducible; each with a skew of the normalized
    // lengths (the half vector's error near v = -l; ref::ScopedHalfVectorSumSkew). The
    // allowance is the largest move: an estimate of the worst case over the 2-ulp ball.
    const double eps = kDirectionInputUlps * 0x1p-23;
    for (uint32_t pattern = 0; pattern < kConditioningPatterns; ++pattern) {
      double sign = pattern % 2 ? -1.0 : 1.0;
      perturbed = record;
      for (size_t c = 0; c < directionColumns.size(); ++c) {
        uint32_t bit = (static_cast<uint32_t>(c + 1) * 0x9E3779B9u >> (7 + pattern / 2)) & 1u;
        perturbed[directionColumns[c]] *= 1.0 + (bit ? sign : -sign) * eps;
      }
      ref::ScopedHalfVectorSumSkew skew(sign * eps);
      program.reference(perturbed.data(), moved.data());
      for (uint32_t k = 0; k < layout.outStride; ++k) {
        double d = std::abs(moved[k] - ref[k]);
        if (std::isfinite(d)) {
          double& c = run.conditioning[i * layout.outStride + k];
          c = std::max(c, d);
        }
      }
    }
  }
  run.inputs = std::move(inputs);
  return run;
}

std::vector<uint32_t> directionInputColumns(const ProbeLayout& layout) {
  std::vector<uint32_t> cols;
  for (const char* name : {"n", "v", "l"})
    if (const ProbeInput* in = layout.find(name); in && in->type == ValueType::Vec3)
      for (uint32_t k = 0; k < 3; ++k) cols.push_back(in->offset + k);
  return cols;
}

ErrorStats compare(const ProbeRun& run, const ProbeProgram& program) {
  ErrorStats s;
  uint32_t stride = program.shader.layout.outStride;
  for (uint64_t i = 0; i < run.count; ++i)
    for (uint32_t k = 0; k < stride; ++k)
      s.add(static_cast<int64_t>(i), run.gpu[i * stride + k], run.reference[i * stride + k], program.tolerance,
            run.conditioning.empty() ? 0.0 : run.conditioning[i * stride + k]);
  return s;
}

}  // namespace mb
