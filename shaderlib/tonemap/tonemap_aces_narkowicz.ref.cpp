// Reference for tonemap_aces_narkowicz: Narkowicz 2015's fit, per channel,
//   f(x) = clamp((a x^2 + b x) / (c x^2 + d x + e), 0, 1),
//   a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14.
#include "common/reference.hpp"

namespace mb::ref {

static double narkowiczCurve(double x) {
  const double a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
  return clamp01((a * x * x + b * x) / (c * x * x + d * x + e));
}

static Vec3 tonemapAcesNarkowicz(Vec3 color) {
  return {narkowiczCurve(color.x), narkowiczCurve(color.y), narkowiczCurve(color.z)};
}

MB_REFERENCE("tonemap_aces_narkowicz", tonemapAcesNarkowicz);

}  // namespace mb::ref
