// Reference for f0_metallic_filament: dielectric F0 = 0.16 reflectance^2 (Filament's remap of
// [0, 1] to [0, 16%]), blended with the metal's base colour by metallic.
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 f0MetallicFilament(Vec3 baseColor, double metallic, double reflectance) {
  double dielectricF0 = 0.16 * reflectance * reflectance;
  return mix(splat(dielectricF0), baseColor, metallic);
}

MB_REFERENCE("f0_metallic_filament", f0MetallicFilament);

}  // namespace mb::ref
