// Reference for f0_clearcoat_exact: the base IOR from f0 (against air), then the normal-
// incidence reflectance against the coat, ((n_base - 1.5)/(n_base + 1.5))^2.
#include "common/reference.hpp"

namespace mb::ref {

static double channel(double f0) {
  const double coatIor = 1.5;
  double s = std::sqrt(f0);
  if (s >= 1.0) return 1.0;  // n_base -> infinity: total reflection
  double baseIor = (1.0 + s) / (1.0 - s);
  double r = (baseIor - coatIor) / (baseIor + coatIor);
  return r * r;
}

static Vec3 f0ClearcoatExact(Vec3 f0) { return {channel(f0.x), channel(f0.y), channel(f0.z)}; }

MB_REFERENCE("f0_clearcoat_exact", f0ClearcoatExact);
MB_GROUND_TRUTH("f0_clearcoat_exact", f0ClearcoatExact);

}  // namespace mb::ref
