// Sphere-light quantities in double, shared by the references and ground truths of the light
// bricks (sphere_horizon_wrap, sphere_max_noh, sphere_energy_normalization, sphere_light_d).
// The sphere light is seen from the shading point as a spherical cap: centre direction c = g.l
// (unit), angular radius a with sin(a) = sourceRadius / distance ("sinAlpha").
// Every quantity here is computed from its definition (an integral or a maximum over the cap),
// never from the approximations the bricks implement.
#pragma once
#include <algorithm>
#include <cmath>

#include "common/ibl_reference.hpp"

namespace mb::ref::lights {

// GGX D (Walter et al. 2007, eq. 33) in pbrt-v4's tan^2 form, as a function of n.h.
inline double ggxD(double NoH, double alpha) {
  double cos2 = NoH * NoH;
  if (cos2 == 0.0) return alpha * alpha / kPi;  // the limit (cos^2 + sin^2 / alpha^2)^-2 / (pi alpha^2)
  double tan2 = (1.0 - cos2) / cos2;
  double e = 1.0 + tan2 / (alpha * alpha);
  return 1.0 / (kPi * alpha * alpha * cos2 * cos2 * e * e);
}

// Two unit vectors completing the unit vector a to an orthonormal frame.
struct Frame {
  Vec3 u, w;
};
inline Frame frameAround(const Vec3& a) {
  Vec3 helper = std::fabs(a.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  Vec3 u = normalize(cross(helper, a));
  return {u, cross(a, u)};
}
inline Vec3 onCone(const Vec3& axis, const Frame& f, double cosT, double sinT, double phi) {
  return axis * cosT + (f.u * std::cos(phi) + f.w * std::sin(phi)) * sinT;
}

// n.h for the light direction l (unit): h = normalize(v + l). v = -l has no half vector; n is
// used as in makeGeometry.
inline double nohFor(const Geometry& g, const Vec3& l) {
  Vec3 s = g.v + l;
  double len2 = dot(s, s);
  return len2 > 1e-24 ? dot(g.n, s) / std::sqrt(len2) : 1.0;
}

// Mirror direction of v about n.
inline Vec3 reflectionOf(const Geometry& g) { return g.n * (2.0 * dot(g.n, g.v)) - g.v; }

// Exact max of n.h over the cap. n.h is 1 at l = r (mirror direction), so if r lies in the cap
// the max is 1; otherwise it is on the cap's boundary circle, found by a 4096-point scan in
// azimuth refined by golden-section search (converges to ~1e-15 in n.h).
inline double maxNoHOverCap(const Geometry& g, double sinAlpha) {
  const Vec3& c = g.l;
  if (sinAlpha <= 0.0) return nohFor(g, c);
  double cosAlpha = std::sqrt(1.0 - sinAlpha * sinAlpha);
  if (dot(reflectionOf(g), c) >= cosAlpha) return 1.0;
  Frame f = frameAround(c);
  auto at = [&](double phi) { return nohFor(g, onCone(c, f, cosAlpha, sinAlpha, phi)); };
  const int n = 4096;
  double step = 2.0 * kPi / n, bestPhi = 0.0, best = -2.0;
  for (int i = 0; i < n; ++i) {
    double value = at(i * step);
    if (value > best) best = value, bestPhi = i * step;
  }
  double lo = bestPhi - step, hi = bestPhi + step;
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int it = 0; it < 80; ++it) {
    double m1 = hi - ratio * (hi - lo), m2 = lo + ratio * (hi - lo);
    if (at(m1) < at(m2))
      lo = m1;
    else
      hi = m2;
  }
  return std::max(best, at(0.5 * (lo + hi)));
}

// UE4 SphereHorizonCosWrap, accurate branch (CapsuleLight.ush; seed 002), the closed-form
// irradiance of a sphere crossing the horizon (Snyder 1996, Area Light Sources for Real-Time
// Graphics), written literally: for -sin a < n.l < sin a, with cos b = n.l,
//   x = sqrt(1/sin^2 a - 1), y = -x / tan b, z = sin b sqrt(1 - y^2),
//   n.l' = (n.l acos(y) - x z + atan(z / x) / sin^2 a) / pi.
// sin a = 0 (a point light) is its limit max(n.l, 0), where the literal form is 0/0.
inline double sphereHorizonCosAccurate(const Geometry& g, double sinAlpha) {
  double NoL = dot(g.n, g.l);
  if (NoL >= sinAlpha) return NoL;
  if (sinAlpha == 0.0) return 0.0;
  NoL = std::max(NoL, -sinAlpha);
  double sinAlphaSqr = sinAlpha * sinAlpha;
  double cosBeta = NoL, sinBeta = std::sqrt(1.0 - cosBeta * cosBeta);
  double tanBeta = sinBeta / cosBeta;
  double x = std::sqrt(1.0 / sinAlphaSqr - 1.0);
  double y = -x / tanBeta;
  double z = sinBeta * std::sqrt(std::max(0.0, 1.0 - y * y));
  return (NoL * std::acos(std::clamp(y, -1.0, 1.0)) - x * z + std::atan(z / x) / sinAlphaSqr) / kPi;
}

// The scalar state of UE4's SphereMaxNoH (seed 002) before its optional Newton step: the rim
// point l cos a + T sin a towards the mirror ray, as dot products (RoL = 2 NoL NoV - VoL,
// rInvLengthT = sin a / sqrt(1 - RoL^2), NoTr, VoTr). `inside`: the mirror ray hits the
// sphere (n.h = 1); `point`: sin a = 0 (no rim; n.h of the centre).
struct DecimaRim {
  bool inside = false, point = false;
  double NoL = 0, NoV = 0, VoL = 0, cosAlpha = 1, RoL = 0, rInvLengthT = 0, NoTr = 0, VoTr = 0;
};
inline DecimaRim decimaRim(const Geometry& g, double sinAlpha) {
  DecimaRim d;
  d.NoL = dot(g.n, g.l), d.NoV = dot(g.n, g.v), d.VoL = dot(g.v, g.l);
  d.point = sinAlpha <= 0.0;
  if (d.point) return d;
  d.cosAlpha = std::sqrt(1.0 - sinAlpha * sinAlpha);
  d.RoL = 2.0 * d.NoL * d.NoV - d.VoL;
  d.inside = d.RoL >= d.cosAlpha;
  if (d.inside) return d;
  d.rInvLengthT = sinAlpha / std::sqrt(1.0 - d.RoL * d.RoL);
  d.NoTr = d.rInvLengthT * (d.NoV - d.RoL * d.NoL);
  d.VoTr = d.rInvLengthT * (2.0 * d.NoV * d.NoV - 1.0 - d.RoL * d.VoL);
  return d;
}
// n.h for l' = l cos a + Tr (given as NoTr, VoTr): (NoL' + NoV) / sqrt(2 + 2 VoL').
inline double decimaNoH(const DecimaRim& d, double NoTr, double VoTr) {
  double NoL2 = d.NoL * d.cosAlpha + NoTr, VoL2 = d.VoL * d.cosAlpha + VoTr;
  return clamp01((NoL2 + d.NoV) / std::sqrt(2.0 + 2.0 * VoL2));
}

// Irradiance from a uniform sphere light, normalized by that of a point light of the same
// intensity facing the surface (pi L sin^2 a):  (1 / (pi sin^2 a)) Int_cap max(n.l, 0) dw.
// Polar coordinates (theta, phi) about c, phi measured from n's projection: n.l =
// A + B cos(phi) with A = cos(theta) n.c, B = sin(theta) |n - (n.c) c|, whose positive part
// integrates in closed form over phi; theta by composite Gauss-Legendre (64 x 8), which is
// exact up to the two kinks where |A| = B (self-convergence 64 vs 256 panels: < 1e-9).
inline double sphereIrradianceOverPoint(const Geometry& g, double sinAlpha, int panels = 64) {
  double NoC = dot(g.n, g.l);
  if (sinAlpha <= 0.0) return std::max(NoC, 0.0);
  static const detail_ibl::GaussLegendre<8> gl;
  double sinNC = std::sqrt(std::max(0.0, 1.0 - NoC * NoC));
  double alpha = std::asin(sinAlpha), sum = 0.0, h = alpha / panels;
  for (int p = 0; p < panels; ++p) {
    for (int i = 0; i < 8; ++i) {
      double theta = h * (p + 0.5 + 0.5 * gl.x[i]);
      double A = std::cos(theta) * NoC, B = std::sin(theta) * sinNC, phiIntegral;
      if (A >= B)
        phiIntegral = 2.0 * kPi * A;
      else if (A <= -B)
        phiIntegral = 0.0;
      else {
        double phi0 = std::acos(-A / B);
        phiIntegral = 2.0 * (A * phi0 + B * std::sin(phi0));
      }
      sum += 0.5 * h * gl.w[i] * phiIntegral * std::sin(theta);
    }
  }
  return sum / (kPi * sinAlpha * sinAlpha);
}

// Int_cap f(l) dw over the sphere light's cap (centre g.l, sin of its angular radius
// sinAlpha), for an f that peaks, at the scale of alpha, at the mirror direction r where GGX
// D does. Quadrature in polar coordinates (t, phi) about r: for each phi the cap is one
// interval [t0, t1] in t (cos(angle to c) = R cos(t - delta)), integrated by 12-point
// Gauss-Legendre on panels that grow geometrically from t0 (the peak seen along that phi) at
// the scale of alpha; phi by composite Gauss-Legendre over the whole circle when r is inside
// the cap, else over the azimuth range that meets the cap after
// phi = phi0 + dphi sin(pi u / 2), which removes the square-root ends of that range.
template <class F>
double capIntegral(const Geometry& g, double alpha, double sinAlpha, F f, int phiPanels) {
  const Vec3& c = g.l;
  static const detail_ibl::GaussLegendre<12> glT;
  static const detail_ibl::GaussLegendre<8> glPhi;
  Vec3 r = normalize(reflectionOf(g));
  double cosAlpha = std::sqrt(1.0 - sinAlpha * sinAlpha);
  double cosD = std::clamp(dot(r, c), -1.0, 1.0);
  // Towards c, in r's tangent plane. Where the mirror ray passes through the centre, c and r
  // agree to rounding and c - r cosD is rounding noise with a component along r: the frame
  // built from it was not orthogonal to r, and the integral came out 1.003x to 4.8x too large
  // (issue 14; the 2.33x reported). A second projection keeps e in r's tangent plane.
  Vec3 e = c - r * cosD;
  e = e - r * dot(e, r);
  double sinD = length(e);
  Frame fr = sinD > 1e-300 ? Frame{e / sinD, cross(r, e / sinD)} : frameAround(r);
  // Integral over t of f sin t for one azimuth phi (measured from e).
  auto alongPhi = [&](double phi) {
    double A = cosD, B = sinD * std::cos(phi);
    double R = std::sqrt(A * A + B * B);
    if (R < cosAlpha) return 0.0;
    double delta = std::atan2(B, A), half = std::acos(std::min(1.0, cosAlpha / R));
    double t0 = std::max(0.0, delta - half), t1 = std::min(kPi, delta + half);
    double sum = 0.0, a = t0, width = 0.05 * alpha;
    while (a < t1) {
      double b = std::min(t1, a + width);
      for (int i = 0; i < 12; ++i) {
        double t = 0.5 * (a + b) + 0.5 * (b - a) * glT.x[i];
        sum += 0.5 * (b - a) * glT.w[i] * f(onCone(r, fr, std::cos(t), std::sin(t), phi)) * std::sin(t);
      }
      a = b;
      width *= 2.0;
    }
    return sum;
  };
  double integral = 0.0;
  bool rInside = cosD >= cosAlpha;
  // Azimuth range meeting the cap: all of it if the cap contains r or -r.
  double dphi = kPi;
  if (!rInside && sinD > sinAlpha) dphi = std::asin(sinAlpha / sinD);
  for (int p = 0; p < phiPanels; ++p) {
    for (int i = 0; i < 8; ++i) {
      double u = -1.0 + (2.0 * p + 1.0 + glPhi.x[i]) / phiPanels;  // in [-1, 1]
      double wu = glPhi.w[i] / phiPanels;
      if (rInside || dphi >= kPi) {
        integral += wu * kPi * alongPhi(kPi * u);
      } else {
        double phi = dphi * std::sin(0.5 * kPi * u);
        integral += wu * dphi * 0.5 * kPi * std::cos(0.5 * kPi * u) * alongPhi(phi);
      }
    }
  }
  return integral;
}

// The sphere light's effective GGX D: the D a point light of the sphere's intensity
// (pi L sin^2 a, in irradiance at normal incidence) would need to give the same specular,
// treating the Smith and Fresnel factors as constant over the cap (as every representative-
// point method does):  D_eff = (1 / (pi sin^2 a)) Int_cap D(n.h(l)) dw,  the whole cap (the
// horizon is the business of sphere_horizon_wrap). -> D(n.h(c)) as a -> 0.
inline double sphereEffectiveDWith(const Geometry& g, double alpha, double sinAlpha, int phiPanels) {
  if (sinAlpha <= 0.0) return ggxD(nohFor(g, g.l), alpha);
  auto D = [&](const Vec3& l) { return ggxD(std::max(0.0, nohFor(g, l)), alpha); };
  return capIntegral(g, alpha, sinAlpha, D, phiPanels) / (kPi * sinAlpha * sinAlpha);
}

inline double sphereEffectiveD(const Geometry& g, double alpha, double sinAlpha) {
  return sphereEffectiveDWith(g, alpha, sinAlpha, 256);
}

// The energy normalization a max-n.h representative point needs: D_eff / D(max n.h), i.e. the
// factor that turns the peak D into the sphere's integrated D. 1 for a point light.
inline double sphereNormalizationTruth(const Geometry& g, double alpha, double sinAlpha) {
  return sphereEffectiveD(g, alpha, sinAlpha) / ggxD(maxNoHOverCap(g, sinAlpha), alpha);
}

}  // namespace mb::ref::lights
