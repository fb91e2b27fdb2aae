// Reference for tube_point_min_angle: the point P(t) = L0 + t Ld, t in [0, 1], maximizing the
// cosine to the mirror ray, f(t) = (a + b t) / sqrt(c + 2 d t + e t^2) with a = r.L0, b = r.Ld,
// c = |L0|^2, d = L0.Ld, e = |Ld|^2. f'(t) = 0 at t* = (a d - b c) / (b d - a e) (the t^2 terms
// cancel), so the maximum over [0, 1] is among f(0), f(1) and f(t*) when t* lies inside.
// Then the sphere step of Karis 2013 eqs. 11-12 with the tube's radius, and the direction.
// Ground truth: the direction of the capsule closest in angle to r (tube_lights_reference.hpp),
// which equals this brick for a zero radius; with a radius, the brick's sphere step (a point
// towards the line of r) and the ball's tangent direction differ.
#include "common/tube_lights_reference.hpp"

namespace mb::ref {

static Vec3 tubePointMinAngle(Geometry g, Vec3 L0, Vec3 L1, double sourceRadius) {
  Vec3 r = g.n * (2.0 * dot(g.n, g.v)) - g.v;
  Vec3 Ld = L1 - L0;
  double a = dot(r, L0), b = dot(r, Ld), c = dot(L0, L0), d = dot(L0, Ld), e = dot(Ld, Ld);
  auto cosine = [&](double t) { return (a + b * t) / std::sqrt(c + 2.0 * d * t + e * t * t); };
  double best = 0.0;
  if (cosine(1.0) > cosine(0.0)) best = 1.0;
  double den = b * d - a * e;
  if (den != 0.0) {
    double tStar = (a * d - b * c) / den;
    if (tStar > 0.0 && tStar < 1.0 && cosine(tStar) > cosine(best)) best = tStar;
  }
  Vec3 L = L0 + Ld * best;
  return normalize(tubes::sphereClosestPoint(L, r, sourceRadius));
}

MB_REFERENCE("tube_point_min_angle", tubePointMinAngle);
MB_GROUND_TRUTH("tube_point_min_angle", tubes::capsuleClosestDirection);

}  // namespace mb::ref
