// Reference for kd_urp: the refracted fraction 1 - F (energy not reflected specularly) times
// the dielectric fraction 1 - metallic (seed 003).
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 kdUrp(Vec3 F, double metallic) {
  Vec3 kS = F;
  Vec3 kD = splat(1.0) - kS;
  return kD * (1.0 - metallic);
}

MB_REFERENCE("kd_urp", kdUrp);

}  // namespace mb::ref
