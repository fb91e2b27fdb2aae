// Reference for diffuse_disney_burley: Burley 2012 sec. 5.3,
//   f_d = baseColor/pi (1 + (F_D90 - 1)(1 - cos theta_l)^5)(1 + (F_D90 - 1)(1 - cos theta_v)^5),
//   F_D90 = 0.5 + 2 roughness cos^2 theta_d, with cos theta_d = l.h.
#include "common/reference.hpp"

namespace mb::ref {

static double diffuseDisneyBurley(Geometry g, double roughness, double) {
  double fd90 = 0.5 + 2.0 * roughness * g.LoH * g.LoH;
  double lightTerm = 1.0 + (fd90 - 1.0) * std::pow(1.0 - g.NoL, 5.0);
  double viewTerm = 1.0 + (fd90 - 1.0) * std::pow(1.0 - g.NoV, 5.0);
  return lightTerm * viewTerm / kPi;
}

MB_REFERENCE("diffuse_disney_burley", diffuseDisneyBurley);

}  // namespace mb::ref
