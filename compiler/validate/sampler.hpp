// Seeded, stratified probe inputs. Geometry inputs are vectors (n, v, l) in a random frame,
// with n.v and n.l stratified over the domain, a share of samples concentrated near the
// specular peak (n.h -> 1, log-spaced angles down to 1e-5 rad) and fixed edge cases (v = l = n,
// grazing view, grazing light). Scalars are stratified (Latin hypercube) over their ranges,
// with the range ends among the edge cases. Values are rounded to fp32: the GPU and the
// reference see the same numbers.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "emit/emitter.hpp"

namespace mb {

struct SampleDomain {
  std::map<std::string, Range> ranges;  // per non-geometry input
  GeometryDomain geometry;
  // The library's roughness inputs by name (ShaderLibrary::roughnessKinds), set by
  // domainAtPrecision: stress adds their fp32 and fp16 floors to its candidates.
  std::map<std::string, RoughnessKind> roughness;
};

std::vector<float> generateSamples(const ProbeLayout& layout, const SampleDomain& domain, uint64_t count,
                                   uint64_t seed);

// Deterministic on every platform (std distributions are not).
class SplitMix64 {
 public:
  explicit SplitMix64(uint64_t seed) : state_(seed) {}
  uint64_t next();
  double uniform();  // [0, 1)

 private:
  uint64_t state_;
};

}  // namespace mb
