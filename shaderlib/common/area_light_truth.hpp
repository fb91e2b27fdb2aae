// Brute-force ground truth of what a sphere or tube light sends towards the viewer (issue 14,
// item 5): the GGX specular lobe and the Lambert cosine integrated over the light's solid
// angle in double, with no representative point, no normalization and no horizon wrap. A
// light of uniform radiance L gives the specular radiance L Int D V F (n.l)+ dw and the
// diffuse L (c / pi) Int (n.l)+ dw. The representative-point method replaces the first by
// E D(l_rep) k V(l_c) F(l_c) wrap(l_c) and the second by E (c / pi) wrap(l_c), with E the
// illuminance of the point light standing in for the light (docs/models/lights.md); the bench
// `mb_bench_area_lights` compares the two.
// D: GGX (lights::ggxD, Walter et al. 2007 eq. 33, 0 where n.h <= 0); V: exact height-correlated
// Smith (Heitz 2014 eq. 99, microfacet_reference.hpp); F = 1 (every method takes F at one
// direction; its error is not the light's).
// Quadrature: lights::capIntegral (sphere) and tubes::CapsuleQuadrature (capsule), both
// graded towards the lobe's peak at the mirror direction.
#pragma once
#include "common/microfacet_reference.hpp"
#include "common/tube_lights_reference.hpp"

namespace mb::ref::arealights {

struct LobeIntegrals {
  double specular = 0;  // Int D V (n.l)+ dw
  double diffuse = 0;   // Int (n.l)+ dw
  double solidAngle = 0;
};

// The lobe at the unit light direction l: D V (n.l)+, 0 below the horizon.
inline double specularAt(const Geometry& g, double alpha, const Vec3& l) {
  double NoL = dot(g.n, l);
  if (!(NoL > 0.0)) return 0.0;
  double NoV = std::max(dot(g.n, g.v), kMinNoV);
  return lights::ggxD(std::max(0.0, lights::nohFor(g, l)), alpha) * smithGgxCorrelatedV(NoV, NoL, alpha) * NoL;
}

// The sphere light's cap: centre g.l, sin of its angular radius sinAlpha (> 0).
inline LobeIntegrals sphereLobe(const Geometry& g, double alpha, double sinAlpha, int phiPanels = 256) {
  LobeIntegrals out;
  out.specular = lights::capIntegral(
      g, alpha, sinAlpha, [&](const Vec3& l) { return specularAt(g, alpha, l); }, phiPanels);
  out.diffuse = lights::capIntegral(
      g, alpha, sinAlpha, [&](const Vec3& l) { return std::max(0.0, dot(g.n, l)); }, phiPanels);
  out.solidAngle = 2.0 * kPi * sinAlpha * sinAlpha / (1.0 + std::sqrt(1.0 - sinAlpha * sinAlpha));
  return out;
}

// The tube light's capsule (segment L0 -> L1 relative to the shading point, radius R > 0, not
// seen end-on).
inline LobeIntegrals tubeLobe(const Geometry& g, double alpha, const Vec3& L0, const Vec3& L1, double R,
                              double lobeFraction = 0.02) {
  LobeIntegrals out;
  tubes::CapsuleChart ch(L0, L1, R);
  if (ch.endOn) return out;
  tubes::CapsuleQuadrature q(g, alpha, ch, lobeFraction);
  out.specular = q.integrate([&](const Vec3& l) { return specularAt(g, alpha, l); });
  out.diffuse = q.integrate([&](const Vec3& l) { return std::max(0.0, dot(g.n, l)); });
  out.solidAngle = q.integrate([](const Vec3&) { return 1.0; });
  return out;
}

}  // namespace mb::ref::arealights
