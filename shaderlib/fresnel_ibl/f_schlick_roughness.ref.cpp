// Reference for f_schlick_roughness: F = F0 + (max(1 - roughness, F0) - F0) (1 - cos theta_v)^5.
#include <algorithm>

#include "common/reference.hpp"

namespace mb::ref {

static Vec3 fSchlickRoughness(Geometry g, Vec3 f0, double roughness) {
  double weight = std::pow(clamp01(1.0 - g.NoV), 5.0);
  double grazing = 1.0 - roughness;
  Vec3 f90{std::max(grazing, f0.x), std::max(grazing, f0.y), std::max(grazing, f0.z)};
  return f0 + (f90 - f0) * weight;
}

MB_REFERENCE("f_schlick_roughness", fSchlickRoughness);

}  // namespace mb::ref
