// Runs one brick's probe over many records and keeps, per record, the GPU value, the double
// reference and the tolerance the brick is validated against (manifest abs + rel |ref| plus
// the input-conditioning allowance of runProbe). The energy checks integrate these values;
// they build and run shaders only through validate/probe_program.hpp.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "common/reference.hpp"
#include "harness/vulkan_harness.hpp"
#include "validate/probe_program.hpp"

namespace mb::energy {

// Every input an energy probe may take, by the probe's input name.
struct ProbeInputs {
  ref::Vec3 n{0, 0, 1}, v{0, 0, 1}, l{0, 0, 1};
  double alpha = 0, perceptualRoughness = 0;  // specular_*, diffuse
  ref::Vec3 t{1, 0, 0};                       // specular_*_aniso: tangent and roughnesses
  double at = 0, ab = 0;
  ref::Vec3 f0{1, 1, 1};  // energy_compensation
  double dfgY = 1;
};

// Writes `in` into one record of `layout` (rounded to fp32). Throws std::logic_error for an
// input name it does not know (a slot the energy checks were not written for).
void packRecord(const ProbeLayout& layout, const ProbeInputs& in, float* dst);

struct BrickValues {
  std::vector<float> gpu;         // output component 0 per record
  std::vector<double> reference;  // the same, in double
  std::vector<double> tolerance;  // |gpu - reference| allowed per record
  uint64_t outsideTolerance = 0;  // records where the brick misses its own tolerance
  double gpuMs = 0;
};

// Probes built once per brick (compiling is the expensive part).
class ProbeCache {
 public:
  explicit ProbeCache(const ShaderLibrary& lib) : lib_(lib) {}
  const ProbeProgram& get(const Brick& brick);

 private:
  const ShaderLibrary& lib_;
  std::map<std::string, ProbeProgram> programs_;
};

// Record i is recordAt(i), i < count (generated on the fly: a furnace run has ~10^6 records).
BrickValues sweepBrick(harness::VulkanHarness& gpu, const ProbeProgram& program, size_t count,
                       const std::function<ProbeInputs(size_t)>& recordAt);

// Reference-only evaluation (no GPU) of component 0 at the same fp32-rounded record.
double referenceAt(const ProbeProgram& program, const ProbeInputs& in);

// |prod gpu_k - prod ref_k| <= sum_k tol_k prod_{j<k} |ref_j| prod_{j>k} |gpu_j| (telescoping):
// the error bound of a product of bricks at record i.
double productBound(const std::vector<const BrickValues*>& factors, size_t i);

}  // namespace mb::energy
