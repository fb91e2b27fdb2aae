// Reference for tube_point_karis: Karis 2013, eqs. 15-16 (seed 002) as written,
//   t = ((r.L0)(r.Ld) - (L0.Ld)) / (|Ld|^2 - (r.Ld)^2),  l = || L0 + saturate(t) Ld ||,
// followed by the sphere representative point of eqs. 11-12 about that point with the tube's
// radius: centerToRay = (L.r) r - L, closestPoint = L + centerToRay saturate(R / |centerToRay|).
// r = 2 (n.v) n - v. t = 0/0 (r parallel to Ld) takes t = 0 as the brick does.
// Ground truth: the direction of the capsule closest in angle to r (tube_lights_reference.hpp).
#include "common/tube_lights_reference.hpp"

namespace mb::ref {

static Vec3 tubePointKaris(Geometry g, Vec3 L0, Vec3 L1, double sourceRadius) {
  Vec3 r = g.n * (2.0 * dot(g.n, g.v)) - g.v;
  Vec3 Ld = L1 - L0;
  double numerator = dot(r, L0) * dot(r, Ld) - dot(L0, Ld);
  double denominator = dot(Ld, Ld) - dot(r, Ld) * dot(r, Ld);
  double t = denominator != 0.0 ? clamp01(numerator / denominator) : 0.0;
  Vec3 L = L0 + Ld * t;
  return normalize(tubes::sphereClosestPoint(L, r, sourceRadius));
}

MB_REFERENCE("tube_point_karis", tubePointKaris);
MB_GROUND_TRUTH("tube_point_karis", tubes::capsuleClosestDirection);

}  // namespace mb::ref
