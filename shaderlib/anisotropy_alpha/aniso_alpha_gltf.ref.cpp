// Reference for aniso_alpha_gltf: KHR_materials_anisotropy, alpha_t = alpha (1 - s^2) + s^2
// (the spec's mix(alpha, 1, s^2) expanded), alpha_b = alpha.
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 anisoAlphaGltf(double alpha, double strength) {
  double s2 = strength * strength;
  return {alpha * (1.0 - s2) + s2, alpha, 0.0};
}

MB_REFERENCE("aniso_alpha_gltf", anisoAlphaGltf);

}  // namespace mb::ref
