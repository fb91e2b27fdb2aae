// Reference for importance_sample_ggx: inverse-CDF sampling of D(h) cos(theta_h) for GGX
// (Walter et al. 2007 eq. 35): tan^2(theta) = alpha^2 u2 / (1 - u2), phi = 2 pi u1, mapped to
// world space with the frame of Karis 2013's listing (the frame is part of the mapping).
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 importanceSampleGgx(Geometry g, double u1, double u2, double alpha) {
  double cosTheta, sinTheta;
  if (u2 >= 1.0) {
    cosTheta = 0.0;
    sinTheta = 1.0;
  } else {
    double tan2 = alpha * alpha * u2 / (1.0 - u2);
    cosTheta = 1.0 / std::sqrt(1.0 + tan2);
    sinTheta = std::sqrt(tan2) * cosTheta;
  }
  double phi = 2.0 * kPi * u1;
  Vec3 up = std::fabs(g.n.z) < 0.999 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  Vec3 tangentX = normalize(cross(up, g.n));
  Vec3 tangentY = cross(g.n, tangentX);
  return tangentX * (sinTheta * std::cos(phi)) + tangentY * (sinTheta * std::sin(phi)) + g.n * cosTheta;
}

MB_REFERENCE("importance_sample_ggx", importanceSampleGgx);

}  // namespace mb::ref
