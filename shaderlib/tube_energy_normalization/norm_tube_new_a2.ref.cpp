// Reference for norm_tube_new_a2: UE4 EnergyNormalization (ShadingModels.ush, the #if 1 line
// branch; seed 002), as written:
//   New_a2(a2, SinAlpha, VoH) = a2 + 0.25 SinAlpha (3 sqrt(a2) + SinAlpha) / (VoH + 0.001)
//   Sphere_a2 = New_a2(a2, SphereSinAlpha, VoH);  Energy = a2 / Sphere_a2
//   LineTanAlpha = sqrt((1.0001 - LineCosTwoAlpha) / (1 + LineCosTwoAlpha))
//   Line_a2 = New_a2(Sphere_a2, LineTanAlpha, VoH);  Energy *= sqrt(Sphere_a2 / Line_a2)
// SphereSinAlpha = sourceRadius / |centre|, LineCosTwoAlpha = L0.L1 / (|L0| |L1|); both terms
// always applied (a tube). Ground truth: as norm_tube_karis.
#include "common/tube_lights_reference.hpp"

namespace mb::ref {

static double newA2(double a2, double sinAlpha, double VoH) {
  return a2 + 0.25 * sinAlpha * (3.0 * std::sqrt(a2) + sinAlpha) / (VoH + 0.001);
}

static double normTubeNewA2(Geometry g, double alpha, Vec3 L0, Vec3 L1, double sourceRadius) {
  double a2 = alpha * alpha;
  double sphereSinAlpha = sourceRadius / length((L0 + L1) * 0.5);
  double sphereA2 = newA2(a2, sphereSinAlpha, g.VoH);
  double energy = a2 / sphereA2;
  double lineCosTwoAlpha = dot(L0, L1) / (length(L0) * length(L1));
  double lineTanAlpha = std::sqrt((1.0001 - lineCosTwoAlpha) / (1.0 + lineCosTwoAlpha));
  double lineA2 = newA2(sphereA2, lineTanAlpha, g.VoH);
  energy *= std::sqrt(sphereA2 / lineA2);
  return energy;
}

MB_REFERENCE("norm_tube_new_a2", normTubeNewA2);
MB_GROUND_TRUTH("norm_tube_new_a2", tubes::tubeNormalizationTruth);

}  // namespace mb::ref
