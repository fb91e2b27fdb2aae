#include "validate/probe_program.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/model_reference.hpp"
#include "common/reference.hpp"

namespace mb {
namespace {

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void compileInto(ProbeProgram& p) {
  auto t0 = std::chrono::steady_clock::now();
  p.compiled = compileComputeGlsl(p.shader.glsl, p.shader.fileName);
  p.compileMs = msSince(t0);
}

[[noreturn]] void missingReference(const std::string& what) {
  throw DiagnosticError({{Severity::Error, "E-NO-REFERENCE", {"shaderlib/manifest.json", 0, 0},
                          what + " has no registered C++ reference", ""}});
}

}  // namespace

ProbeProgram buildBrickProbe(const ShaderLibrary& lib, const Brick& brick, bool unstableVariant) {
  ProbeProgram p;
  p.shader = emitBrickProbe(lib, brick, unstableVariant);
  compileInto(p);
  const ref::Reference* r = ref::Registry::references().find(brick.id);
  if (!r) missingReference("brick '" + brick.id + "'");
  p.reference = r->eval;
  p.tolerance = brick.tolerance;
  p.domain.ranges = brick.domain;
  p.domain.geometry = brick.geometry;
  return p;
}

ProbeProgram buildPermutationProbe(const ShaderLibrary& lib, const Permutation& perm) {
  const MaterialDesc& mat = *perm.material;
  ProbeProgram p;
  p.shader = emitPermutation(lib, perm);
  compileInto(p);
  ref::ModelReferenceFn model = ref::ModelRegistry::instance().find(mat.model);
  if (!model) missingReference("model '" + mat.model + "'");

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

  for (const auto& prm : mat.params)
    if (!prm.constant) p.domain.ranges[prm.name] = prm.range;

  ProbeLayout layout = p.shader.layout;
  p.reference = [model, layout, &mat](const double* in, double* out) {
    ref::ModelEvalInput e;
    auto vec = [&](const std::string& name) {
      const ProbeInput* pi = layout.find(name);
      return ref::Vec3{in[pi->offset], in[pi->offset + 1], in[pi->offset + 2]};
    };
    e.n = vec("n");
    e.v = vec("v");
    e.l = vec("l");
    e.bricks = mat.bricks;
    for (const auto& prm : mat.params) {
      if (prm.constant) {
        e.inputs[prm.name] = prm.value;
      } else {
        const ProbeInput* pi = layout.find(prm.name);
        e.inputs[prm.name].assign(in + pi->offset, in + pi->offset + componentCount(prm.type));
      }
    }
    ref::Vec3 r = model(e);
    out[0] = r.x;
    out[1] = r.y;
    out[2] = r.z;
  };
  return p;
}

ProbeRun runProbe(harness::VulkanHarness& gpu, const ProbeProgram& program, std::vector<float> inputs) {
  const ProbeLayout& layout = program.shader.layout;
  ProbeRun run;
  run.count = layout.inStride ? inputs.size() / layout.inStride : 0;
  auto kernel = gpu.createKernel(program.compiled.spirv);
  auto result = gpu.run(*kernel, inputs, layout.inStride, layout.outStride, run.count);
  run.gpu = std::move(result.outputs);
  run.gpuMs = result.gpuMs;

  run.reference.resize(run.count * layout.outStride);
  run.conditioning.assign(run.count * layout.outStride, 0.0);
  std::vector<uint32_t> directionColumns = directionInputColumns(layout);
  std::vector<double> record(layout.inStride), perturbed(layout.inStride), moved(layout.outStride);
  for (uint64_t i = 0; i < run.count; ++i) {
    for (uint32_t k = 0; k < layout.inStride; ++k) record[k] = inputs[i * layout.inStride + k];
    double* ref = run.reference.data() + i * layout.outStride;
    program.reference(record.data(), ref);
    if (directionColumns.empty()) continue;
    // Two opposite sign patterns on the vector components (direction error), fixed per
    // column so that runs are reproducible, each with a skew of the normalized lengths
    // (the half vector's error near v = -l; ref::ScopedHalfVectorSumSkew).
    const double eps = kDirectionInputUlps * 0x1p-23;
    for (double sign : {1.0, -1.0}) {
      perturbed = record;
      for (size_t c = 0; c < directionColumns.size(); ++c) {
        double s = ((c * 0x9E3779B9u >> 7) & 1u) ? sign : -sign;
        perturbed[directionColumns[c]] *= 1.0 + s * eps;
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
      s.add(static_cast<int64_t>(i), run.gpu[i * stride + k], run.reference[i * stride + k],
            program.tolerance, run.conditioning.empty() ? 0.0 : run.conditioning[i * stride + k]);
  return s;
}

}  // namespace mb
