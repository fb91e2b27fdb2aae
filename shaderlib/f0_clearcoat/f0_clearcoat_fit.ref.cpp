// Reference for f0_clearcoat_fit: the cubic -0.263008 f0^3 + 0.941892 f0^2 + 0.346479 f0 -
// 0.0285998, clamped to [0, 1] (Filament). Ground truth: the exact interface F0 it fits,
// ((n_base - 1.5)/(n_base + 1.5))^2 with n_base = (1 + sqrt f0)/(1 - sqrt f0)
// (f0_clearcoat_exact).
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 f0ClearcoatFit(Vec3 f0) {
  auto cubic = [](double x) { return clamp01(-0.263008 * x * x * x + 0.941892 * x * x + 0.346479 * x - 0.0285998); };
  return {cubic(f0.x), cubic(f0.y), cubic(f0.z)};
}

static double exactChannel(double f0) {
  const double coatIor = 1.5;
  double s = std::sqrt(f0);
  if (s >= 1.0) return 1.0;
  double baseIor = (1.0 + s) / (1.0 - s);
  double r = (baseIor - coatIor) / (baseIor + coatIor);
  return r * r;
}

static Vec3 f0ClearcoatExact(Vec3 f0) { return {exactChannel(f0.x), exactChannel(f0.y), exactChannel(f0.z)}; }

MB_REFERENCE("f0_clearcoat_fit", f0ClearcoatFit);
MB_GROUND_TRUTH("f0_clearcoat_fit", f0ClearcoatExact);

}  // namespace mb::ref
