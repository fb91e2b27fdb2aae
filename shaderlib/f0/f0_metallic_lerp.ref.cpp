// Reference for f0_metallic_lerp: dielectrics reflect 4% at normal incidence (IOR 1.5), metals
// their base colour: F0 = (1 - metallic) 0.04 + metallic baseColor.
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 f0MetallicLerp(Vec3 baseColor, double metallic, double) {
  return splat(0.04) * (1.0 - metallic) + baseColor * metallic;
}

MB_REFERENCE("f0_metallic_lerp", f0MetallicLerp);

}  // namespace mb::ref
