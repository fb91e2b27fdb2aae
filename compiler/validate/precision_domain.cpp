#include "validate/precision_domain.hpp"

#include <algorithm>

namespace mb {

double roughnessFloor(RoughnessKind kind, ShaderPrecision p) {
  switch (kind) {
    case RoughnessKind::Alpha:
      return minAlpha(p);
    case RoughnessKind::Perceptual:
      return minPerceptualRoughness(p);
    case RoughnessKind::None:
      break;
  }
  return 0.0;
}

SampleDomain domainAtPrecision(const ShaderLibrary& lib, const SampleDomain& declared, ShaderPrecision p) {
  SampleDomain d = declared;
  d.roughness = lib.roughnessKinds();
  if (p == ShaderPrecision::Fp32) return d;
  // An fp16 probe converts its inputs to half: beyond 65504 they would arrive as Inf, so
  // ranges (e.g. a light's illuminance) stop at the largest finite half.
  const double kHalfMax = 65504.0;
  for (auto& [name, range] : d.ranges) {
    double floor = roughnessFloor(lib.roughnessKind(name), p);
    if (range.hi > floor) range.lo = std::max(range.lo, floor);
    range.lo = std::max(range.lo, -kHalfMax);
    range.hi = std::min(range.hi, kHalfMax);
  }
  return d;
}

}  // namespace mb
