// The adversarial input set of `matbricks stress` (docs/stress.md). Every record is tagged
// in or out of the probe's domain; only in-domain NaN/Inf fail.
//   geometry (probes with n, v, l; local frame n = +z, so the dot products are exact):
//     n.v, n.l in {0, 1e-7, 1e-4, 1e-2, 0.1, 0.5, 1} plus the declared domain's ends, with l
//     on the mirror side (n.v = n.l gives n.h = 1 exactly), the same side (n.v = n.l gives
//     v = l) and at 90 degrees azimuth; v = -l (exactly and nearly: l.h -> 0); back-facing l
//     and v; zero-length n, v, l; each case with the vectors scaled by 1e-3 and 1e3 (one at a
//     time and all together), as interpolation leaves them;
//   parameters: the declared range's ends and middle, 0, 1e-4, 1 and, for roughness-like
//     inputs (precision_domain.hpp), the fp32 and fp16 minimum clamps; vec3 parameters take
//     splatted values, signed ones (a direction such as a tangent) axis and diagonal vectors;
//     combined in full when that is small, else one input at a time;
//   plus `randomSamples` records of the validation sampler (in domain).
// In domain: raw n.v and n.l (of the normalized vectors) inside the declared geometry ranges,
// every parameter inside its range, no zero-length vector (zero-length vec3 parameters with
// signed ranges included) and, at fp16, vectors of unit length: |1e3 v|^2 overflows half
// (65504) and |1e-3 v|^2 is subnormal, so fp16 shading normalizes in fp32 first.
#pragma once
#include <cstdint>
#include <vector>

#include "emit/emitter.hpp"
#include "emit/precision.hpp"
#include "validate/sampler.hpp"

namespace mb {

struct StressInputs {
  std::vector<float> records;     // count * layout.inStride
  std::vector<uint8_t> inDomain;  // one per record
  uint64_t count() const { return inDomain.size(); }
};

StressInputs generateStressInputs(const ProbeLayout& layout, const SampleDomain& domain, ShaderPrecision precision,
                                  uint64_t randomSamples, uint64_t seed);

}  // namespace mb
