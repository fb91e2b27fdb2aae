// Reference for norm_new_a2: UE4 EnergyNormalization's sphere term (seed 002):
//   New_a2(a2, SinAlpha, VoH) = a2 + 0.25 SinAlpha (3 sqrt(a2) + SinAlpha) / (VoH + 0.001),
//   Energy = a2 / New_a2.
// Ground truth: D_eff / D(max n.h) as for norm_sphere_karis.
#include "common/lights_reference.hpp"

namespace mb::ref {

static double normNewA2(Geometry g, double alpha, double sinAlpha) {
  double a2 = alpha * alpha;
  double newA2 = a2 + 0.25 * sinAlpha * (3.0 * std::sqrt(a2) + sinAlpha) / (g.VoH + 0.001);
  return a2 / newA2;
}

MB_REFERENCE("norm_new_a2", normNewA2);
MB_GROUND_TRUTH("norm_new_a2", lights::sphereNormalizationTruth);

}  // namespace mb::ref
