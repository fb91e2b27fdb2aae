// Exact anisotropic Smith-GGX quantities in double for the specular_v_aniso references, in
// pbrt-v4's form (TrowbridgeReitzDistribution::Lambda/G1/G, after Heitz 2014 eqs. 86, 98, 99):
//   Lambda(w) = (-1 + sqrt(1 + alpha_o^2 tan^2(theta_w))) / 2,
//   alpha_o^2 = cos^2(phi_w) at^2 + sin^2(phi_w) ab^2,
// with theta_w, phi_w the angles of w in the Gram-Schmidt frame of (n, t). At n.w = 0
// (tan^2 = inf) Lambda is infinite; the visibilities take their finite limits there:
// Lambda(w) ~ alpha_o / (2 cos theta_w), so G1(w) / cos theta_w -> 2 / alpha_o.
#pragma once
#include "common/aniso_reference.hpp"

namespace mb::ref::aniso_v {

// alpha_o of Heitz 2014 eq. 80 (the roughness projected on the azimuth of w).
inline double projectedAlpha(const LocalAngles& w, double at, double ab) {
  return std::sqrt(w.cos2Phi * at * at + w.sin2Phi * ab * ab);
}

inline double lambda(const LocalAngles& w, double at, double ab) {
  double a = projectedAlpha(w, at, ab);
  return (-1.0 + std::sqrt(1.0 + a * a * w.tan2Theta)) / 2.0;
}

// The angles of v (with cos theta = the clamped n.v) and l (the clamped n.l).
struct ViewLight {
  LocalAngles v, l;
  double NoV, NoL;
};

inline ViewLight viewLight(const Geometry& g, const Vec3& tangent) {
  AnisoFrame f = anisoFrame(g.n, tangent);
  return {localAngles(f, g.v, g.NoV), localAngles(f, g.l, g.NoL), g.NoV, g.NoL};
}

// Height-correlated: V = 1 / (4 n.l n.v (1 + Lambda(v) + Lambda(l))) (eq. 99).
inline double correlated(const ViewLight& w, double at, double ab) {
  if (w.NoL == 0.0) return 1.0 / (2.0 * w.NoV * projectedAlpha(w.l, at, ab));
  return 1.0 / (4.0 * w.NoL * w.NoV * (1.0 + lambda(w.v, at, ab) + lambda(w.l, at, ab)));
}

// Separable: V = G1(v) G1(l) / (4 n.l n.v), G1 = 1 / (1 + Lambda) (eq. 98).
inline double separable(const ViewLight& w, double at, double ab) {
  double g1v = 1.0 / (1.0 + lambda(w.v, at, ab));
  if (w.NoL == 0.0) return g1v * (2.0 / projectedAlpha(w.l, at, ab)) / (4.0 * w.NoV);
  double g1l = 1.0 / (1.0 + lambda(w.l, at, ab));
  return g1v * g1l / (4.0 * w.NoL * w.NoV);
}

}  // namespace mb::ref::aniso_v
