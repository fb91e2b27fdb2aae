// Image-based-lighting quantities in double, shared by references and ground truths of the
// env_brdf and mip_mapping bricks.
#pragma once
#include <array>
#include <cmath>

#include "common/microfacet_reference.hpp"

namespace mb::ref {

// The split-sum DFG integrals (Karis 2013; DESIGN.md "DFG LUT convention") for GGX with the
// exact height-correlated Smith visibility, at n.v = NoV and linear roughness alpha:
//   x = Int Gv Fc,  y = Int Gv,  Gv = 4 V (n.l)(v.h)/(n.h),  Fc = (1 - v.h)^5,
// where the integral is the expectation over half vectors h distributed as D(h)(n.h).
// Quadrature (deterministic, no sampling noise): h is parameterized by the GGX CDF
// u -> cos^2(theta_h) = (1 - u)/(1 + (alpha^2 - 1) u) and the azimuth phi; for each u the set
// of phi with n.l > 0 is the interval [0, phiMax] (n.l = 2 (v.h)(n.h) - n.v > 0 is
// cos(phi) > kappa), so the phi integral is a smooth Gauss-Legendre integral on that
// interval. In u the range splits where phiMax leaves pi and where it reaches 0 (found by
// bisection); both parts use composite Gauss-Legendre (32 panels x 8 nodes), the second
// after a cosine substitution that removes the square-root behaviour of phiMax at its ends.
// Self-convergence (32 vs 128 panels): < 1e-6 absolute for n.v >= 0.1 at moderate roughness,
// < 5e-6 at n.v = 0.01, ~2e-4 at n.v = 1e-3. At low roughness it is worse: at n.v = 1,
// alpha = 0.04 the 32-panel default gives 0.998364 for Int Gv, 128 panels 0.998322, 512
// panels 0.998298, and the independent half-vector quadrature of compiler/energy 0.998297,
// i.e. the default is off by ~7e-5 there (found by the energy checks; docs/energy.md).
struct DfgIntegrals {
  double gvFc = 0;  // channel 0
  double gv = 0;    // channel 1
};

namespace detail_ibl {
// Gauss-Legendre nodes/weights on [-1, 1] (computed once by Newton on P_n).
template <int N>
struct GaussLegendre {
  std::array<double, N> x{}, w{};
  GaussLegendre() {
    for (int i = 0; i < N; ++i) {
      double z = std::cos(kPi * (i + 0.75) / (N + 0.5));
      for (int it = 0; it < 100; ++it) {
        double p0 = 1, p1 = 0;
        for (int k = 1; k <= N; ++k) {
          double p2 = p1;
          p1 = p0;
          p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
        }
        double dp = N * (z * p0 - p1) / (z * z - 1.0);
        double dz = p0 / dp;
        z -= dz;
        if (std::fabs(dz) < 1e-16) {
          x[i] = z;
          w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
          break;
        }
      }
    }
  }
};
}  // namespace detail_ibl

inline DfgIntegrals dfgIntegrals(double NoV, double alpha, int panels = 32) {
  static const detail_ibl::GaussLegendre<8> glU;
  static const detail_ibl::GaussLegendre<32> glPhi;
  NoV = std::min(1.0, std::max(NoV, 1e-7));
  const double sinV = std::sqrt(std::max(0.0, 1.0 - NoV * NoV));
  const double a2 = alpha * alpha;
  auto cos2H = [&](double u) { return (1.0 - u) / ((1.0 - u) + a2 * u); };
  // Azimuth range [0, phiMax(u)] with n.l > 0; phiMax falls from pi (h near n) to 0.
  auto phiMax = [&](double u) {
    double c2 = cos2H(u), NoH = std::sqrt(c2), sinH = std::sqrt(std::max(0.0, 1.0 - c2));
    double target = NoV / (2.0 * NoH) - NoV * NoH, denom = sinV * sinH;
    if (denom <= 0.0) return target < 0.0 ? kPi : 0.0;
    double kappa = target / denom;
    return kappa >= 1.0 ? 0.0 : (kappa <= -1.0 ? kPi : std::acos(kappa));
  };
  // F(u) = (1/pi) Int_0^phiMax Gv (Fc) dphi  (phi in [0, pi] by symmetry)
  auto azimuthal = [&](double u, double& fx, double& fy) {
    fx = fy = 0.0;
    double pm = phiMax(u);
    if (pm <= 0.0) return;
    double c2 = cos2H(u), NoH = std::sqrt(c2), sinH = std::sqrt(std::max(0.0, 1.0 - c2));
    for (int j = 0; j < 32; ++j) {
      double phi = 0.5 * pm * (1.0 + glPhi.x[j]);
      double VoH = sinV * sinH * std::cos(phi) + NoV * NoH;
      double NoL = 2.0 * VoH * NoH - NoV;
      if (NoL <= 0.0 || VoH <= 0.0) continue;
      double Gv = 4.0 * smithGgxCorrelatedV(NoV, NoL, alpha) * NoL * VoH / NoH;
      fx += glPhi.w[j] * Gv * std::pow(1.0 - VoH, 5.0);
      fy += glPhi.w[j] * Gv;
    }
    fx *= 0.5 * pm / kPi;
    fy *= 0.5 * pm / kPi;
  };
  // uFull: end of the full-azimuth range; uNone: start of the empty one (bisection).
  auto bisect = [&](bool wantFull) {
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 80; ++it) {
      double mid = 0.5 * (lo + hi), pm = phiMax(mid);
      bool inside = wantFull ? pm >= kPi : pm > 0.0;
      (inside ? lo : hi) = mid;
    }
    return lo;
  };
  double uFull = bisect(true), uNone = bisect(false);
  DfgIntegrals r;
  // [0, uFull]: smooth integrand, composite Gauss-Legendre.
  for (int p = 0; p < panels; ++p) {
    double u0 = uFull * p / panels, u1 = uFull * (p + 1) / panels;
    for (int i = 0; i < 8; ++i) {
      double u = 0.5 * (u0 + u1) + 0.5 * (u1 - u0) * glU.x[i], fx, fy;
      azimuthal(u, fx, fy);
      r.gvFc += 0.5 * (u1 - u0) * glU.w[i] * fx;
      r.gv += 0.5 * (u1 - u0) * glU.w[i] * fy;
    }
  }
  // [uFull, uNone]: phiMax has square-root behaviour at both ends; u = uFull + (uNone -
  // uFull)(1 - cos(pi s))/2 makes the integrand smooth in s.
  double span = uNone - uFull;
  if (span > 0.0) {
    for (int p = 0; p < panels; ++p) {
      double s0 = double(p) / panels, s1 = double(p + 1) / panels;
      for (int i = 0; i < 8; ++i) {
        double sv = 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * glU.x[i];
        double u = uFull + span * 0.5 * (1.0 - std::cos(kPi * sv));
        double jac = span * 0.5 * kPi * std::sin(kPi * sv), fx, fy;
        azimuthal(u, fx, fy);
        r.gvFc += 0.5 * (s1 - s0) * glU.w[i] * jac * fx;
        r.gv += 0.5 * (s1 - s0) * glU.w[i] * jac * fy;
      }
    }
  }
  return r;
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
