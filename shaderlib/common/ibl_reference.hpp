// Image-based-lighting quantities in double, shared by references and ground truths of the
// env_brdf and mip_mapping bricks.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>

#include "common/microfacet_reference.hpp"
#include "common/quadrature_reference.hpp"

namespace mb::ref {

// The split-sum DFG integrals (Karis 2013; DESIGN.md "DFG LUT convention") for GGX with the
// exact height-correlated Smith visibility, at n.v = NoV and linear roughness alpha:
//   x = Int Gv Fc,  y = Int Gv,  Gv = 4 V (n.l)(v.h)/(n.h),  Fc = (1 - v.h)^5,
// where the integral is the expectation over half vectors h distributed as D(h)(n.h).
//
// Adaptive quadrature (no sampling noise; quadrature_reference.hpp), accurate to the
// requested absolute tolerance everywhere, grazing n.v and the smoothest LUT rows included:
// - Outer variable x = ln tan(theta_h). With t = tan^2 = e^(2x), D(h)(n.h) dw_h becomes
//   (alpha^2 t / (pi (alpha^2 + t)^2)) dx dphi: a smooth bump of width ~1 around x = ln alpha
//   whatever alpha is (in u or theta it is a peak of width alpha^2 or alpha). Below
//   x = ln alpha - 16 the bump holds e^-32 of the mass and is dropped.
// - n.l = 2 (v.h)(n.h) - n.v = cos(2 theta) n.v + sin(2 theta) sin(theta_v) cos(phi), so
//   n.l > 0 <=> cos(phi) > kappa = -cos(2 theta) n.v / (sin(2 theta) sin(theta_v)): every
//   azimuth for theta <= thetaFull = (pi/2 - theta_v)/2, none from thetaNone =
//   (pi/2 + theta_v)/2 on, and |phi| < acos(kappa) between (closed forms, no search).
//   [x(thetaFull), x(thetaNone)] is integrated after x = a + (b - a)(1 - cos(pi s))/2, which
//   removes the square-root behaviour of acos(kappa) at both ends.
// - Inner: (1/pi) Int_0^phiMax Gv dphi by the same adaptive rule (the integrand has structure
//   of width ~alpha in n.l where it falls to 0 at phiMax, which a fixed rule misses).
// Convergence is tested (tests/test_integral_references.cpp): tolerance 1e-10 against 1e-13,
// and against independent quadratures.
struct DfgIntegrals {
  double gvFc = 0;  // channel 0
  double gv = 0;    // channel 1
};

namespace detail_ibl {
template <int N>
using GaussLegendre = detail_quad::GaussLegendre<N>;

// The azimuth range with n.l > 0 at tan^2(theta_h) = t for a view at NoV (sin sinV):
// cos(phi) > kappa. Returns phiMax in [0, pi].
inline double azimuthLimit(double t, double NoV, double sinV) {
  if (sinV <= 0.0) return t < 1.0 ? kPi : 0.0;
  const double kappa = -(1.0 - t) * NoV / (2.0 * std::sqrt(t) * sinV);
  return kappa >= 1.0 ? 0.0 : (kappa <= -1.0 ? kPi : std::acos(kappa));
}

// The ends of the partial-azimuth range, as x = ln tan(theta_h).
struct AzimuthBreaks {
  double xFull, xNone;
};
inline AzimuthBreaks azimuthBreaks(double NoV) {
  const double thetaV = std::acos(NoV);
  return {std::log(std::tan(0.25 * kPi - 0.5 * thetaV)), std::log(std::tan(0.25 * kPi + 0.5 * thetaV))};
}

// Integrates g over [a, b] in panels no wider than `width`, and over [b, c] after the
// cosine substitution b + (c - b)(1 - cos(pi s))/2; g returns K values.
template <size_t K, class G>
std::array<double, K> integrateOuter(AdaptiveGaussLegendre<K>& rule, const G& g, double a, double b, double c,
                                     double width, double tol) {
  std::array<double, K> total{};
  auto add = [&](const std::array<double, K>& v) {
    for (size_t k = 0; k < K; ++k) total[k] += v[k];
  };
  const int panels = b > a ? std::max(1, static_cast<int>(std::ceil((b - a) / width))) : 0;
  const int sPanels = c > b ? std::max(1, static_cast<int>(std::ceil((c - b) / width))) : 0;
  const double share = tol / std::max(1, panels + sPanels);
  for (int p = 0; p < panels; ++p)
    add(rule.integrate(g, a + (b - a) * p / panels, a + (b - a) * (p + 1) / panels, share));
  if (c > b) {
    const double span = c - b;
    auto substituted = [&](double s) {
      std::array<double, K> v = g(b + span * 0.5 * (1.0 - std::cos(kPi * s)));
      const double jac = span * 0.5 * kPi * std::sin(kPi * s);
      for (auto& e : v) e *= jac;
      return v;
    };
    for (int p = 0; p < sPanels; ++p)
      add(rule.integrate(substituted, double(p) / sPanels, double(p + 1) / sPanels, share));
  }
  return total;
}
}  // namespace detail_ibl

inline DfgIntegrals dfgIntegrals(double NoV, double alpha, double tolerance = 1e-10) {
  NoV = std::min(1.0, std::max(NoV, 1e-7));
  // alpha = 0: the mirror limit, h = n, G2 = 1, so Gv = 1 and Fc = (1 - n.v)^5.
  if (!(alpha > 0.0)) return {std::pow(1.0 - NoV, 5.0), 1.0};
  const double sinV = std::sqrt(std::max(0.0, 1.0 - NoV * NoV));
  const double a2 = alpha * alpha;
  AdaptiveGaussLegendre<2> outer;
  // (1/pi) Int_0^phiMax (Gv Fc, Gv) dphi at tan^2(theta_h) = t.
  auto azimuthal = [&](double t, double innerTolerance) -> std::array<double, 2> {
    const double pm = detail_ibl::azimuthLimit(t, NoV, sinV);
    if (pm <= 0.0) return {0.0, 0.0};
    const double NoH = 1.0 / std::sqrt(1.0 + t), sinH = std::sqrt(t) * NoH;
    auto f = [&](double phi) -> std::array<double, 2> {
      const double VoH = sinV * sinH * std::cos(phi) + NoV * NoH;
      const double NoL = 2.0 * VoH * NoH - NoV;
      if (NoL <= 0.0 || VoH <= 0.0) return {0.0, 0.0};
      const double Gv = 4.0 * smithGgxCorrelatedV(NoV, NoL, alpha) * NoL * VoH / NoH;
      return {Gv * std::pow(1.0 - VoH, 5.0), Gv};
    };
    AdaptiveGaussLegendre<2> inner;
    std::array<double, 2> r = inner.integrate(f, 0.0, pm, innerTolerance * kPi);
    return {r[0] / kPi, r[1] / kPi};
  };
  // Outer weight: 2 alpha^2 t / (alpha^2 + t)^2 dx (integrates to 1 over the real line).
  auto g = [&](double x) -> std::array<double, 2> {
    const double t = std::exp(2.0 * x), w = 2.0 * a2 * t / ((a2 + t) * (a2 + t));
    if (!(w > 0.0)) return {0.0, 0.0};
    // The weighted inner error stays at 1e-4 of the outer tolerance: below the outer rule's
    // floor (1/100 of its share).
    std::array<double, 2> m = azimuthal(t, std::min(1.0, 1e-4 * tolerance / w));
    return {w * m[0], w * m[1]};
  };
  const detail_ibl::AzimuthBreaks br = detail_ibl::azimuthBreaks(NoV);
  const double xLow = std::min(std::log(alpha) - 16.0, br.xFull);
  std::array<double, 2> r = detail_ibl::integrateOuter(outer, g, xLow, br.xFull, br.xNone, 2.0, tolerance);
  return {r[0], r[1]};
}

// Split-sum specular environment BRDF with Schlick's F (f90 = 1) inside the integral:
//   Int Gv (f0 + (1 - f0) Fc) = f0 Int Gv + (1 - f0) Int Gv Fc, per channel.
inline Vec3 envBrdfIntegral(const Vec3& f0, double perceptualRoughness, double NoV) {
  DfgIntegrals d = dfgIntegrals(NoV, perceptualRoughness * perceptualRoughness);
  return f0 * d.gv + (splat(1.0) - f0) * d.gvFc;
}

// The cone-footprint prefiltered-mip level (Unity ImageBasedLighting.hlsl "accurate"
// PerceptualRoughnessToMipmapLevel; seed 000): the GGX lobe of alpha = r^2 is matched to a
// Phong lobe of exponent n = 2/alpha^2 - 2 (Walter et al. 2007 eq. 21 style mapping), the
// exponent is moved from n.h to n.r space (n / (4 n.r), Knald "Lys" notes), and mapped back
// to a perceptual roughness r' = (2 / (n' + 2))^(1/4); mip = r' * maxMip. alpha = 0 is the
// mirror limit r' = 0.
inline double coneFootprintMip(double perceptualRoughness, double NoR, double maxMip) {
  double alpha = perceptualRoughness * perceptualRoughness;
  if (alpha == 0.0) return 0.0;
  double n = 2.0 / (alpha * alpha) - 2.0;
  n /= 4.0 * NoR;
  double r = std::pow(2.0 / (n + 2.0), 0.25);
  return r * maxMip;
}

}  // namespace mb::ref
