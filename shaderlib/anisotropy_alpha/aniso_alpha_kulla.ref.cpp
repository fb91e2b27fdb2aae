// Reference for aniso_alpha_kulla: Kulla & Conty 2017, p. 20, alpha_x = alpha (1 + a),
// alpha_y = alpha (1 - a), written as alpha + alpha a and alpha - alpha a.
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 anisoAlphaKulla(double alpha, double anisotropy) {
  return {alpha + alpha * anisotropy, alpha - alpha * anisotropy, 0.0};
}

MB_REFERENCE("aniso_alpha_kulla", anisoAlphaKulla);

}  // namespace mb::ref
