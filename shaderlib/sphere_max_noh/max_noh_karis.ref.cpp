// Reference for max_noh_karis: Karis 2013, eqs. 11-12, the closest point on the sphere to the
// reflection ray,  closestPoint = L + centerToRay * saturate(sourceRadius / |centerToRay|),
// centerToRay = (L.r) r - L, with L = distance * c; then n.h for l = normalize(closestPoint).
// Ground truth: the exact max of n.h over the sphere's cap (what the point stands in for: the
// point of the light with the largest D).
#include "common/lights_reference.hpp"

namespace mb::ref {

static double maxNoHKaris(Geometry g, double sinAlpha) {
  const double distance = 1.0, sourceRadius = sinAlpha * distance;
  Vec3 r = lights::reflectionOf(g);
  Vec3 L = g.l * distance;
  Vec3 centerToRay = r * dot(L, r) - L;
  double len = length(centerToRay);
  double k = len > 0.0 ? clamp01(sourceRadius / len) : 1.0;
  Vec3 closestPoint = L + centerToRay * k;
  return clamp01(lights::nohFor(g, normalize(closestPoint)));
}

MB_REFERENCE("max_noh_karis", maxNoHKaris);
MB_GROUND_TRUTH("max_noh_karis", lights::maxNoHOverCap);

}  // namespace mb::ref
