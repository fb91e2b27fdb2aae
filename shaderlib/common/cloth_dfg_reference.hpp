// The cloth channel of the DFG LUT in double, by deterministic quadrature: the directional
// albedo of the Charlie sheen lobe with Ashikhmin's visibility (Filament's cloth DFG,
// CubemapIBL DFV_Charlie_Uniform; DESIGN.md "DFG LUT convention"):
//   E(n.v, alpha) = Int_{n.l > 0} D_Charlie(h) V_Ashikhmin(n.v, n.l) (n.l) dw_l,
//   D_Charlie = (2 + 1/alpha) sin^(1/alpha)(theta_h) / (2 pi)   (Estevez & Kulla 2017, eq. 2)
//   V_Ashikhmin = 1 / (4 (n.l + n.v - n.l n.v))               (Neubelt & Pettineo 2013)
// No Fresnel and no 1/pi: the same quantity Filament's estimator converges to.
// Written over half vectors, dw_l = 4 (v.h) dw_h and dw_h = sin(theta) dtheta dphi. For each
// theta the directions with n.l = 2 (v.h)(n.h) - n.v > 0 are |phi| < phiMax(theta) (as in
// ibl_reference.hpp), an interval on which the integrand is smooth: 32-point Gauss-Legendre.
// In theta the integrand is 0 beyond thetaNone (phiMax = 0), has square-root kinks where
// phiMax leaves pi (thetaFull) and reaches 0, and for small alpha a peak of width ~sqrt(alpha)
// against thetaNone (D grows as sin^(1/alpha)). So [0, thetaFull] and [thetaFull, thetaNone]
// are cut into panels graded geometrically towards thetaNone (a panel is as wide as its
// distance to it, which resolves a peak of any width), each integrated by adaptive
// Gauss-Legendre (8 points against its two halves, absolute tolerance 1e-12).
#pragma once
#include <cmath>
#include <functional>

#include "common/ibl_reference.hpp"

namespace mb::ref {

namespace detail_cloth {

inline double gaussLegendre8(const std::function<double(double)>& f, double lo, double hi) {
  static const detail_ibl::GaussLegendre<8> gl;
  double s = 0.0;
  for (int i = 0; i < 8; ++i) s += gl.w[i] * f(0.5 * (lo + hi) + 0.5 * (hi - lo) * gl.x[i]);
  return 0.5 * (hi - lo) * s;
}

// Int_a^b f, given whole = the 8-point rule on [a, b]: accepted when the two halves agree with
// it to 1e-12, else each half is refined.
inline double adaptiveGaussLegendre(const std::function<double(double)>& f, double a, double b,
                                    double whole, int depth) {
  double m = 0.5 * (a + b), left = gaussLegendre8(f, a, m), right = gaussLegendre8(f, m, b);
  if (depth == 0 || std::fabs(left + right - whole) <= 1e-12) return left + right;
  return adaptiveGaussLegendre(f, a, m, left, depth - 1) + adaptiveGaussLegendre(f, m, b, right, depth - 1);
}

// Int_a^b f on panels [b - (b - a) 2^-k, b - (b - a) 2^-(k+1)], k = 0..29, each adaptive.
// 30 panels: the one against the end is 2^-30 of the range, far below the narrowest peak
// (sqrt(alpha) >= 1.2e-4 at the smallest texel-centre roughness of a 4096 table).
inline double gradedTowardsEnd(const std::function<double(double)>& f, double a, double b) {
  constexpr int kPanels = 30;
  double total = 0.0, lo = a;
  for (int k = 1; k <= kPanels && lo < b; ++k) {
    double hi = k == kPanels ? b : b - (b - a) * std::ldexp(1.0, -k);
    total += adaptiveGaussLegendre(f, lo, hi, gaussLegendre8(f, lo, hi), 40);
    lo = hi;
  }
  return total;
}

}  // namespace detail_cloth

inline double clothDfgIntegral(double NoV, double alpha) {
  static const detail_ibl::GaussLegendre<32> glPhi;
  NoV = std::min(1.0, std::max(NoV, 1e-7));
  const double sinV = std::sqrt(std::max(0.0, 1.0 - NoV * NoV));
  // cos(phi) > kappa(theta) <=> n.l > 0; phiMax falls from pi (h near n) to 0.
  auto phiMax = [&](double theta) {
    double NoH = std::cos(theta), sinH = std::sin(theta);
    double target = NoV / (2.0 * NoH) - NoV * NoH, denom = sinV * sinH;
    if (denom <= 0.0) return target < 0.0 ? kPi : 0.0;
    double kappa = target / denom;
    return kappa >= 1.0 ? 0.0 : (kappa <= -1.0 ? kPi : std::acos(kappa));
  };
  // D(theta) sin(theta) x 2 Int_0^phiMax 4 V (n.l)(v.h) dphi.
  auto integrand = [&](double theta) {
    double pm = phiMax(theta);
    if (pm <= 0.0) return 0.0;
    double NoH = std::cos(theta), sinH = std::sin(theta), inner = 0.0;
    for (int j = 0; j < 32; ++j) {
      double phi = 0.5 * pm * (1.0 + glPhi.x[j]);
      double VoH = sinV * sinH * std::cos(phi) + NoV * NoH;
      double NoL = 2.0 * VoH * NoH - NoV;
      if (NoL <= 0.0 || VoH <= 0.0) continue;
      double V = 1.0 / (4.0 * (NoL + NoV - NoL * NoV));
      inner += glPhi.w[j] * 4.0 * V * NoL * VoH;
    }
    inner *= 0.5 * pm;
    double D = (2.0 + 1.0 / alpha) * std::pow(sinH, 1.0 / alpha) / (2.0 * kPi);
    return D * sinH * 2.0 * inner;
  };
  // thetaFull: end of the full-azimuth range; thetaNone: start of the empty one (bisection).
  auto bisect = [&](bool wantFull) {
    double lo = 0.0, hi = 0.5 * kPi;
    for (int it = 0; it < 80; ++it) {
      double mid = 0.5 * (lo + hi), pm = phiMax(mid);
      bool inside = wantFull ? pm >= kPi : pm > 0.0;
      (inside ? lo : hi) = mid;
    }
    return lo;
  };
  double thetaFull = bisect(true), thetaNone = bisect(false);
  return detail_cloth::gradedTowardsEnd(integrand, 0.0, thetaFull) +
         detail_cloth::gradedTowardsEnd(integrand, thetaFull, thetaNone);
}

}  // namespace mb::ref
