// Reference for sh9_irradiance: E(n) = sum_{l<=2} A_l sum_m L_lm Y_lm(n) (Ramamoorthi &
// Hanrahan 2001 eq. 7-8), with the clamped-cosine convolution A_0 = pi, A_1 = 2 pi / 3,
// A_2 = pi / 4 and the real SH basis Y_lm written from its normalization constants.
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 sh9Irradiance(Vec3 nIn, Vec3 L00, Vec3 L1m1, Vec3 L10, Vec3 L11, Vec3 L2m2, Vec3 L2m1, Vec3 L20, Vec3 L21,
                          Vec3 L22) {
  Vec3 n = normalize(nIn);
  double x = n.x, y = n.y, z = n.z;
  const double y00 = 0.5 * std::sqrt(1.0 / kPi);
  const double y1 = std::sqrt(3.0 / (4.0 * kPi));
  const double y2a = 0.5 * std::sqrt(15.0 / kPi);   // xy, yz, xz
  const double y20 = 0.25 * std::sqrt(5.0 / kPi);   // 3z^2 - 1
  const double y22 = 0.25 * std::sqrt(15.0 / kPi);  // x^2 - y^2
  const double A0 = kPi, A1 = 2.0 * kPi / 3.0, A2 = kPi / 4.0;
  Vec3 band0 = L00 * (y00 * A0);
  Vec3 band1 = (L1m1 * (y1 * y) + L10 * (y1 * z) + L11 * (y1 * x)) * A1;
  Vec3 band2 = (L2m2 * (y2a * x * y) + L2m1 * (y2a * y * z) + L20 * (y20 * (3.0 * z * z - 1.0)) + L21 * (y2a * x * z) +
                L22 * (y22 * (x * x - y * y))) *
               A2;
  return band0 + band1 + band2;
}

MB_REFERENCE("sh9_irradiance", sh9Irradiance);

}  // namespace mb::ref
