// The cloth channel of the DFG LUT in double, by adaptive quadrature: the directional albedo
// of the Charlie sheen lobe with Ashikhmin's visibility (Filament's cloth DFG, CubemapIBL
// DFV_Charlie_Uniform; DESIGN.md "DFG LUT convention"):
//   E(n.v, alpha) = Int_{n.l > 0} D_Charlie(h) V_Ashikhmin(n.v, n.l) (n.l) dw_l,
//   D_Charlie = (2 + 1/alpha) sin^(1/alpha)(theta_h) / (2 pi)   (Estevez & Kulla 2017, eq. 2)
//   V_Ashikhmin = 1 / (4 (n.l + n.v - n.l n.v))               (Neubelt & Pettineo 2013)
// No Fresnel and no 1/pi: the same quantity Filament's estimator converges to.
// Written over half vectors, dw_l = 4 (v.h) dw_h, and with c = cos(theta_h), dw_h = dc dphi:
//   E = Int D(c) [2 Int_0^phiMax(c) 4 V (n.l)(v.h) dphi] dc.
// - Outer variable z = ln c: D = (2 + 1/alpha) (1 - c^2)^(1/(2 alpha)) / (2 pi) is a peak of
//   width ~sqrt(alpha) at c = 0 (theta_h = 90 degrees), so D(c) c dz is a bump of width ~1
//   around z = ln sqrt(alpha) for every alpha. sin^(1/alpha) is formed as
//   exp(log1p(-c^2) / (2 alpha)), exact to rounding for any exponent.
// - The azimuth range with n.l > 0 has the closed-form ends of ibl_reference.hpp: every
//   azimuth for theta_h <= (pi/2 - theta_v)/2, none from (pi/2 + theta_v)/2 on; the partial
//   range between is integrated after the cosine substitution that removes acos's square
//   roots at its ends.
// - Inner: (1/pi) Int_0^phiMax 4 V (n.l)(v.h) dphi by the adaptive rule (at grazing n.v it
//   has structure of width ~n.v in n.l next to phiMax, where V_Ashikhmin ~ 1 / (4 n.l)).
// The tolerance is relative (the albedo reaches ~10^2 at the smallest roughness and n.v, and
// falls to ~1e-15 elsewhere in the smoothest rows): first passes set the scale. Convergence is tested
// (tests/test_integral_references.cpp).
#pragma once
#include <cmath>

#include "common/ibl_reference.hpp"

namespace mb::ref {

inline double clothDfgIntegralAbs(double NoV, double alpha, double tolerance) {
  NoV = std::min(1.0, std::max(NoV, 1e-7));
  const double sinV = std::sqrt(std::max(0.0, 1.0 - NoV * NoV));
  const double coefficient = (2.0 + 1.0 / alpha) / (2.0 * kPi);
  auto g = [&](double z) -> std::array<double, 1> {
    const double c = std::exp(z), c2 = c * c;
    if (!(c2 < 1.0)) return {0.0};
    // Weight D(c) c 2 pi of the inner mean (1/pi) Int.
    const double w = coefficient * std::exp(std::log1p(-c2) / (2.0 * alpha)) * c * 2.0 * kPi;
    const double t = (1.0 - c2) / c2;  // tan^2(theta_h)
    const double pm = detail_ibl::azimuthLimit(t, NoV, sinV);
    if (!(w > 0.0) || pm <= 0.0) return {0.0};
    const double sinH = std::sqrt(1.0 - c2);
    auto f = [&](double phi) -> std::array<double, 1> {
      const double VoH = sinV * sinH * std::cos(phi) + NoV * c;
      const double NoL = 2.0 * VoH * c - NoV;
      if (NoL <= 0.0 || VoH <= 0.0) return {0.0};
      return {NoL * VoH / (NoL + NoV - NoL * NoV)};  // 4 V (n.l)(v.h)
    };
    AdaptiveGaussLegendre<1> inner;
    // As in dfgIntegrals: the weighted inner error stays at 1e-4 of the outer tolerance.
    const double innerTolerance = std::min(1.0, 1e-4 * tolerance / w) * kPi;
    return {w * inner.integrate(f, 0.0, pm, innerTolerance)[0] / kPi};
  };
  // theta_h = thetaNone, thetaFull and 0 as z = ln cos(theta_h) = -ln sqrt(1 + tan^2).
  const detail_ibl::AzimuthBreaks br = detail_ibl::azimuthBreaks(NoV);
  auto zOf = [](double x) { return -0.5 * std::log1p(std::exp(2.0 * x)); };
  const double zNone = zOf(br.xNone), zFull = zOf(br.xFull);
  AdaptiveGaussLegendre<1> outer;
  // Full azimuth on [zFull, 0], partial on [zNone, zFull]: integrateOuter takes the
  // substituted part last, so the variable is mirrored (y = -z).
  auto mirrored = [&](double y) { return g(-y); };
  return detail_ibl::integrateOuter(outer, mirrored, 0.0, -zFull, -zNone, 2.0, tolerance)[0];
}

// Relative tolerance. The albedo spans ~1e-15 (smoothest rows away from grazing: the peak
// lies beyond the visible half vectors) to ~1e3, so passes from 1e-3 absolute tighten the
// tolerance to relativeTolerance x the value found (at most 6 decades per pass; values below
// 1e-30 are returned to 1e-30 absolute).
inline double clothDfgIntegral(double NoV, double alpha, double relativeTolerance = 1e-10) {
  double tol = 1e-3;
  for (;;) {
    const double value = clothDfgIntegralAbs(NoV, alpha, tol);
    const double wanted = std::max(relativeTolerance * std::fabs(value), 1e-30);
    if (wanted >= tol) return value;
    tol = std::max(wanted, tol * 1e-6);
  }
}

}  // namespace mb::ref
