// Reference for diffuse_activision_multiscatter: Chan 2018, "Material Advances in Call of
// Duty: WWII", section 5 (multiscattering diffuse fit), with gloss from the paper's eq. 2,
// alpha^2 = 2 / (1 + 2^(18 g))  =>  g = log2(2 / alpha^2 - 1) / 18, clamped to [0, 1].
// Divided by pi for the slot convention.
#include <algorithm>

#include "common/reference.hpp"

namespace mb::ref {

static double lerp(double a, double b, double t) { return a + (b - a) * t; }

static double glossFromAlpha(double alpha) {
  // Invert eq. 2: 2^(18 g) = 2 / alpha^2 - 1.
  double g = std::log2(2.0 / (alpha * alpha) - 1.0) / 18.0;
  return clamp01(g);
}

static double diffuseActivisionMultiscatter(Geometry g, double, double alpha) {
  double gloss = glossFromAlpha(alpha);
  double f0 = g.LoH + std::pow(1.0 - g.LoH, 5.0);
  double f1 = (1.0 - 0.75 * std::pow(1.0 - g.NoL, 5.0)) * (1.0 - 0.75 * std::pow(1.0 - g.NoV, 5.0));
  double t = clamp01(2.2 * gloss - 0.5);
  double fd = lerp(f0, f1, t);
  double fb = (34.5 * gloss * gloss - 59.0 * gloss + 24.5) * g.LoH *
              std::exp2(-std::max(73.2 * gloss - 21.2, 8.9) * std::sqrt(g.NoH));
  return std::max(fd + fb, 0.0) / kPi;
}

MB_REFERENCE("diffuse_activision_multiscatter", diffuseActivisionMultiscatter);

}  // namespace mb::ref
