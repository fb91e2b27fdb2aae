#include "energy/brick_sweep.hpp"

#include <cmath>
#include <stdexcept>

namespace mb::energy {

void packRecord(const ProbeLayout& layout, const ProbeInputs& in, float* dst) {
  auto put3 = [](float* p, const ref::Vec3& v) {
    p[0] = static_cast<float>(v.x);
    p[1] = static_cast<float>(v.y);
    p[2] = static_cast<float>(v.z);
  };
  static const std::map<std::string, double ProbeInputs::*> scalars{
      {"alpha", &ProbeInputs::alpha},
      {"perceptualRoughness", &ProbeInputs::perceptualRoughness},
      {"at", &ProbeInputs::at},
      {"ab", &ProbeInputs::ab},
      {"dfgY", &ProbeInputs::dfgY}};
  static const std::map<std::string, ref::Vec3 ProbeInputs::*> vectors{{"n", &ProbeInputs::n},
                                                                       {"v", &ProbeInputs::v},
                                                                       {"l", &ProbeInputs::l},
                                                                       {"t", &ProbeInputs::t},
                                                                       {"f0", &ProbeInputs::f0}};
  for (const auto& pi : layout.inputs) {
    if (auto s = scalars.find(pi.name); s != scalars.end() && pi.type == ValueType::Float) {
      dst[pi.offset] = static_cast<float>(in.*(s->second));
    } else if (auto v = vectors.find(pi.name); v != vectors.end() && pi.type == ValueType::Vec3) {
      put3(dst + pi.offset, in.*(v->second));
    } else {
      throw std::logic_error("energy checks: no value for probe input '" + pi.name + "'");
    }
  }
}

const ProbeProgram& ProbeCache::get(const Brick& brick) {
  auto it = programs_.find(brick.id);
  if (it == programs_.end()) it = programs_.emplace(brick.id, buildBrickProbe(lib_, brick)).first;
  return it->second;
}

BrickValues sweepBrick(harness::VulkanHarness& gpu, const ProbeProgram& program, size_t count,
                       const std::function<ProbeInputs(size_t)>& recordAt) {
  const ProbeLayout& layout = program.shader.layout;
  std::vector<float> inputs(count * layout.inStride);
  for (size_t i = 0; i < count; ++i) packRecord(layout, recordAt(i), inputs.data() + i * layout.inStride);
  ProbeRun run = runProbe(gpu, program, std::move(inputs));

  BrickValues out;
  out.gpuMs = run.gpuMs;
  out.gpu.resize(run.count);
  out.reference.resize(run.count);
  out.tolerance.resize(run.count);
  const Tolerance& tol = program.tolerance;
  for (uint64_t i = 0; i < run.count; ++i) {
    size_t k = i * layout.outStride;
    out.gpu[i] = run.gpu[k];
    out.reference[i] = run.reference[k];
    out.tolerance[i] = tol.abs + tol.rel * std::abs(run.reference[k]) + run.conditioning[k];
    if (!(std::abs(out.gpu[i] - out.reference[i]) <= out.tolerance[i])) ++out.outsideTolerance;
  }
  return out;
}

double referenceAt(const ProbeProgram& program, const ProbeInputs& in) {
  const ProbeLayout& layout = program.shader.layout;
  std::vector<float> rec(layout.inStride);
  packRecord(layout, in, rec.data());
  std::vector<double> d(rec.begin(), rec.end()), out(layout.outStride);
  program.reference(d.data(), out.data());
  return out[0];
}

double productBound(const std::vector<const BrickValues*>& factors, size_t i) {
  double bound = 0.0;
  for (size_t k = 0; k < factors.size(); ++k) {
    double term = factors[k]->tolerance[i];
    for (size_t j = 0; j < factors.size(); ++j) {
      if (j < k) term *= std::abs(factors[j]->reference[i]);
      if (j > k) term *= std::abs(factors[j]->gpu[i]);
    }
    bound += term;
  }
  return bound;
}

}  // namespace mb::energy
