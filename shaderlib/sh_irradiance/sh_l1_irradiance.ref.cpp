// Reference for sh_l1_irradiance: bands 0 and 1 of E(n) = sum A_l L_lm Y_lm(n), A_0 = pi,
// A_1 = 2 pi / 3, Y00 = 1/(2 sqrt(pi)), Y1m = sqrt(3/(4 pi)) (y, z, x).
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 shL1Irradiance(Vec3 nIn, Vec3 L00, Vec3 L1m1, Vec3 L10, Vec3 L11, Vec3, Vec3, Vec3, Vec3, Vec3) {
  Vec3 n = normalize(nIn);
  const double y00 = 0.5 * std::sqrt(1.0 / kPi), y1 = std::sqrt(3.0 / (4.0 * kPi));
  return L00 * (kPi * y00) + (L1m1 * n.y + L10 * n.z + L11 * n.x) * (2.0 * kPi / 3.0 * y1);
}

MB_REFERENCE("sh_l1_irradiance", shL1Irradiance);

}  // namespace mb::ref
