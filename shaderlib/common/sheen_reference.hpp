// Charlie sheen masking in double (shared by the v_charlie* references and ground truths).
#pragma once
#include <cmath>

#include "common/reference.hpp"

namespace mb::ref {

// Estevez & Kulla 2017, sec. 3: the fitted ln Lambda, L(x) = a / (1 + b x^c) + d x + e with
// the table's r = 0 and r = 1 coefficients blended by t = 1 - (1 - r)^2, mirrored about
// cos = 0.5: Lambda(cos) = exp(L(cos)) below 0.5, exp(2 L(0.5) - L(1 - cos)) above.
inline double charlieFitL(double x, double r) {
  r = clamp01(r);
  double t = 1.0 - (1.0 - r) * (1.0 - r);
  auto blend = [t](double atZero, double atOne) { return (1.0 - t) * atZero + t * atOne; };
  double a = blend(25.3245, 21.5473), b = blend(3.32435, 3.82987), c = blend(0.16801, 0.19823);
  double d = blend(-1.27393, -1.97760), e = blend(-4.85967, -4.32054);
  return a / (1.0 + b * std::pow(x, c)) + d * x + e;
}

inline double charlieFitLambda(double cosTheta, double r) {
  cosTheta = clamp01(cosTheta);  // n.v may exceed 1 by an ulp; cos is defined on [0, 1]
  if (cosTheta < 0.5) return std::exp(charlieFitL(cosTheta, r));
  return std::exp(2.0 * charlieFitL(0.5, r) - charlieFitL(1.0 - cosTheta, r));
}

// The exact Smith Lambda of the Charlie distribution D(m) = (2 + 1/r) sin^(1/r)(theta_m)/(2 pi),
// from its definition (Heitz 2014 eq. 24: the projected area of back-facing microfacets):
//   Lambda(w) = 1/cos(theta_o) * Int_{H^2} max(0, -w.m) D(m) dm.
// The azimuthal integral is analytic: with A = sin(theta_o) sin(theta_m), B = cos(theta_o) cos(theta_m),
// Int_0^{2pi} max(0, -(A cos(phi) + B)) dphi = 2 A sin(phi0) - 2 B (pi - phi0), phi0 = acos(-B/A),
// nonzero only for theta_m > pi/2 - theta_o. The remaining theta_m integral is done by composite
// Simpson on [pi/2 - theta_o, pi/2] (2048 panels; converged to < 1e-7 relative against 20000).
// charlieBackfacingArea returns the integral itself (Lambda * cos theta_o), which stays finite
// at cos theta_o = 0 where Lambda has a 1/cos pole.
inline double charlieBackfacingArea(double cosTheta, double r) {
  cosTheta = std::max(0.0, cosTheta);
  double sinO = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  double lo = kPi / 2 - std::acos(std::min(1.0, cosTheta)), hi = kPi / 2;
  if (hi - lo <= 0.0) return 0.0;
  auto integrand = [&](double thetaM) {
    double A = sinO * std::sin(thetaM), B = cosTheta * std::cos(thetaM);
    if (A <= B) return 0.0;
    double phi0 = std::acos(std::max(-1.0, -B / A));
    double azimuthal = 2.0 * A * std::sin(phi0) - 2.0 * B * (kPi - phi0);
    double D = (2.0 + 1.0 / r) * std::pow(std::sin(thetaM), 1.0 / r) / (2.0 * kPi);
    return azimuthal * D * std::sin(thetaM);
  };
  const int n = 2048;
  double h = (hi - lo) / n, sum = integrand(lo) + integrand(hi);
  for (int i = 1; i < n; ++i) sum += integrand(lo + i * h) * (i % 2 ? 4.0 : 2.0);
  return sum * h / 3.0;
}

inline double charlieExactLambda(double cosTheta, double r) {
  if (cosTheta <= 0.0) return INFINITY;
  return charlieBackfacingArea(cosTheta, r) / cosTheta;
}

// Estevez & Kulla's terminator softening, Lambda' = Lambda^(1 + 2 (1 - cos)^8).
inline double charlieSoften(double lambda, double cosTheta) {
  cosTheta = clamp01(cosTheta);
  return std::pow(lambda, 1.0 + 2.0 * std::pow(1.0 - cosTheta, 8.0));
}

}  // namespace mb::ref
