// Tube (capsule) light quantities in double, shared by the ground truths of the tube-light
// bricks (tube_light_point, tube_energy_normalization). A tube light is the capsule of radius R
// around the segment L0 -> L1, both endpoints given relative to the shading point; the
// capsule is the union of the balls of radius R centred on the segment. Every quantity here
// is computed from its definition (a minimum or an integral over the capsule), never from the
// approximations the bricks implement (Karis 2013 eqs. 15-17; seed 002).
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "common/lights_reference.hpp"

namespace mb::ref::tubes {

using lights::ggxD;
using lights::nohFor;

inline Vec3 mirror(const Geometry& g) { return normalize(lights::reflectionOf(g)); }

// Karis 2013 eqs. 11-12, the sphere light's representative point, as written: for the centre L
// and the mirror direction r, centerToRay = (L.r) r - L and
//   closestPoint = L + centerToRay saturate(sourceRadius / |centerToRay|)
// (|centerToRay| = 0: the saturate's limit 1). The tube bricks apply it to their segment point.
inline Vec3 sphereClosestPoint(const Vec3& L, const Vec3& r, double sourceRadius) {
  Vec3 centerToRay = r * dot(L, r) - L;
  double len = length(centerToRay);
  return L + centerToRay * (len > 0.0 ? clamp01(sourceRadius / len) : 1.0);
}

// Minimizes f over [lo, hi]: an n-point scan, then golden-section search around the best
// sample (f unimodal near its minimum). Returns the argument.
template <class F>
double scanGoldenMin(F f, double lo, double hi, int n = 1024) {
  double step = (hi - lo) / n, bestX = lo, best = f(lo);
  for (int i = 1; i <= n; ++i) {
    double x = lo + i * step, value = f(x);
    if (value < best) best = value, bestX = x;
  }
  double a = std::max(lo, bestX - step), b = std::min(hi, bestX + step);
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int it = 0; it < 100; ++it) {
    double m1 = b - ratio * (b - a), m2 = a + ratio * (b - a);
    if (f(m1) < f(m2))
      b = m2;
    else
      a = m1;
  }
  double x = 0.5 * (a + b);
  return f(x) < best ? x : bestX;
}

// The direction of the capsule closest in angle to the mirror ray r: the representative-point
// method's aim (Karis 2013: the point with the smallest angle to r). The angle from r to ball t
// is angle(r, P(t)) - asin(R / |P(t)|); minimized over t by scan + golden section. If the ray
// meets the capsule (that angle <= 0) the answer is r itself; otherwise it is the ball's
// tangent direction, P^ rotated towards r by asin(R / |P|).
inline Vec3 capsuleClosestDirection(const Geometry& g, const Vec3& L0, const Vec3& L1, double R) {
  Vec3 r = mirror(g), Ld = L1 - L0;
  auto gap = [&](double t) {
    Vec3 p = L0 + Ld * t;
    double len = length(p);
    return std::acos(std::clamp(dot(r, p) / len, -1.0, 1.0)) - std::asin(std::min(1.0, R / len));
  };
  double t = scanGoldenMin(gap, 0.0, 1.0);
  if (gap(t) <= 0.0) return r;
  Vec3 p = L0 + Ld * t, pHat = normalize(p);
  Vec3 towards = r - pHat * dot(r, pHat);
  double lenT = length(towards);
  if (lenT == 0.0) return pHat;  // r = -p^: every direction around p^ is as close
  double beta = std::asin(std::min(1.0, R / length(p)));
  return pHat * std::cos(beta) + towards * (std::sin(beta) / lenT);
}

// ---------------------------------------------------------------------------------------------
// The capsule's solid angle, in gnomonic coordinates. The line's points and the unit normal m
// of the plane through the shading point and the line span a plane Pi that contains the line;
// the point X(t, s) = L0 + t Ld + s m of Pi stands for the direction X^, a bijection onto the
// hemisphere facing Pi, with dw = h0 |Ld| dt ds / |X|^3 (h0: the distance from the shading
// point to the line, which is Pi's distance). Because m is orthogonal to every point C of the
// line, X.C = C'.C (C' = L0 + t Ld), and the direction X^ meets the ball (C(tau), R) iff
// (C'.C)^2 >= (|C'|^2 + s^2)(|C|^2 - R^2) with C'.C > 0. The capsule is the union of these
// balls, so for each t the directions hitting it are |s| <= sMax(t),
//   sMax(t)^2 = max_tau (C'.C(tau))^2 / (|C(tau)|^2 - R^2) - |C'|^2,
// whose maximizer over tau solves a linear equation (the t^2 terms cancel):
//   tau* = (A d - B (c - R^2)) / (B d - A e),  A = C'.L0, B = C'.Ld, c = |L0|^2, d = L0.Ld,
//   e = |Ld|^2; the max over [0, 1] is at tau* (clamped) or at an end.
struct CapsuleChart {
  Vec3 L0, Ld, m, nPi;
  double R = 0, h0 = 0, lenD = 0;
  bool endOn = false;  // the line passes through the shading point: no plane Pi

  CapsuleChart(const Vec3& l0, const Vec3& l1, double radius) : L0(l0), Ld(l1 - l0), R(radius) {
    lenD = length(Ld);
    Vec3 mm = cross(L0, Ld);
    double lm = length(mm);
    endOn = lenD == 0.0 || lm <= 1e-12 * length(L0) * lenD;
    if (endOn) return;
    m = mm / lm;
    nPi = cross(m, Ld / lenD);
    if (dot(nPi, L0) < 0.0) nPi = nPi * -1.0;
    h0 = dot(nPi, L0);
  }
  Vec3 point(double t, double s) const { return L0 + Ld * t + m * s; }
  // sMax(t)^2; negative where the column t misses the capsule.
  double sMax2(double t) const {
    Vec3 c1 = L0 + Ld * t;
    double A = dot(c1, L0), B = dot(c1, Ld), c = dot(L0, L0), d = dot(L0, Ld), e = dot(Ld, Ld);
    double best = -1.0;
    auto consider = [&](double tau) {
      double N = A + B * tau, Q = c + 2.0 * d * tau + e * tau * tau - R * R;
      if (N > 0.0 && Q > 0.0) best = std::max(best, N * N / Q);
    };
    consider(0.0);
    consider(1.0);
    double den = B * d - A * e;
    if (den != 0.0) consider(std::clamp((A * d - B * (c - R * R)) / den, 0.0, 1.0));
    return best < 0.0 ? -1.0 : best - dot(c1, c1);
  }
  // The t range [tMin, tMax] of the capsule's chart (the end caps reach beyond [0, 1]).
  double edge(double inside, double direction) const {
    double step = std::max(R, 1e-12) / lenD, outside = inside + direction * step;
    for (int i = 0; i < 200 && sMax2(outside) >= 0.0; ++i) step *= 2.0, outside = inside + direction * step;
    for (int i = 0; i < 200; ++i) {
      double mid = 0.5 * (inside + outside);
      if (sMax2(mid) >= 0.0)
        inside = mid;
      else
        outside = mid;
    }
    return inside;
  }
  double jacobian(const Vec3& x) const {
    double len = length(x);
    return h0 * lenD / (len * len * len);
  }
};

// Integrates f over [a, b] with 12-point Gauss-Legendre panels that grow geometrically (x2)
// away from every breakpoint in `points` and from both ends, starting at width w0 and capped at
// 1/32 of the piece: resolves a peak of width ~w0 at a breakpoint, square-root behaviour at the
// ends, and the kinks of sMax(t) where the silhouette passes from the cylinder to a cap.
template <class F>
double integrateGraded(F f, double a, double b, std::vector<double> points, double w0) {
  static const detail_ibl::GaussLegendre<12> gl;
  points.push_back(a);
  points.push_back(b);
  std::sort(points.begin(), points.end());
  double sum = 0.0;
  auto panel = [&](double x0, double x1) {
    double s = 0.0;
    for (int i = 0; i < 12; ++i) s += gl.w[i] * f(0.5 * (x0 + x1) + 0.5 * (x1 - x0) * gl.x[i]);
    return 0.5 * (x1 - x0) * s;
  };
  for (size_t k = 0; k + 1 < points.size(); ++k) {
    double lo = std::max(a, points[k]), hi = std::min(b, points[k + 1]);
    if (!(hi > lo)) continue;
    double mid = 0.5 * (lo + hi), w = std::min(w0, 0.25 * (hi - lo)), wMax = (hi - lo) / 32.0;
    for (double x = lo, width = w; x < mid; width = std::min(2.0 * width, wMax)) {
      double y = std::min(mid, x + width);
      sum += panel(x, y);
      x = y;
    }
    for (double x = hi, width = w; x > mid; width = std::min(2.0 * width, wMax)) {
      double y = std::max(mid, x - width);
      sum += panel(y, x);
      x = y;
    }
  }
  return sum;
}

// Int_capsule f(l) dw (l the unit direction) on the chart of `ch`, for an f that peaks at the
// scale of alpha at the mirror direction r, as GGX D does: outer over t in [tMin, tMax] and
// inner over |s| <= sMax(t), both graded towards the peak (the mirror ray's chart point) at the
// lobe's width and towards the square-root ends (integrateGraded).
struct CapsuleQuadrature {
  const CapsuleChart& ch;
  double tMin = 0, tMax = 1, tPeak = 0.5, sPeak = 0, w0 = 0;
  bool faces = false;  // r faces the plane Pi: the chart has a peak point

  CapsuleQuadrature(const Geometry& g, double alpha, const CapsuleChart& chart, double lobeFraction) : ch(chart) {
    Vec3 r = mirror(g);
    tMin = ch.edge(0.0, -1.0), tMax = ch.edge(1.0, 1.0);
    // The mirror ray's point on Pi, if r faces Pi.
    double rPi = dot(ch.nPi, r), scale = length(ch.L0);
    faces = rPi > 0.0;
    if (faces) {
      Vec3 xr = r * (ch.h0 / rPi);
      tPeak = dot(xr - ch.L0, ch.Ld) / (ch.lenD * ch.lenD);
      sPeak = dot(xr, ch.m);
      scale = length(xr);
    }
    // Lobe width on Pi: an angle alpha moves the chart point by ~alpha |X|^2 / h0.
    w0 = lobeFraction * alpha * scale * scale / ch.h0;
  }

  template <class F>
  double integrate(F f) const {
    std::vector<double> tPoints = {0.0, 1.0};
    if (faces && tPeak > tMin && tPeak < tMax) tPoints.push_back(tPeak);
    return integrateGraded(
        [&](double t) {
          double s2 = ch.sMax2(t);
          if (s2 <= 0.0) return 0.0;
          double sm = std::sqrt(s2);
          std::vector<double> sPoints;
          if (faces && sPeak > -sm && sPeak < sm) sPoints.push_back(sPeak);
          return integrateGraded(
              [&](double s) {
                Vec3 x = ch.point(t, s);
                return f(normalize(x)) * ch.jacobian(x);
              },
              -sm, sm, sPoints, w0);
        },
        tMin, tMax, tPoints, w0 / ch.lenD);
  }
};

// The tube light's GGX D averaged over its solid angle, relative to D at the capsule's max n.h:
//   truth = ( Int_capsule D(n.h(w)) dw / Int_capsule dw ) / D(max_capsule n.h).
// This is the factor a representative point's D needs when the point light standing in for
// the tube delivers the tube's L * Omega (the Smith and Fresnel factors and the falloff taken
// as constant over the light, as every representative-point method does). The sphere analogue
// (lights::sphereNormalizationTruth) divides by pi sin^2 a instead of the cap's solid angle
// 2 pi (1 - cos a), 2 / (1 + cos a) apart (<= 1.2 % for sin a <= 0.2).
// Quadrature: outer over t in [tMin, tMax] and inner over |s| <= sMax(t) (the solid angle's
// inner integral in closed form, Int ds / (a^2 + s^2)^1.5 = s / (a^2 sqrt(a^2 + s^2))), both
// graded towards the D peak (the mirror ray's chart point) at the lobe's width and towards the
// square-root ends. R = 0 (a line) is taken as the limit R -> 0 (R = 1e-7 |L0|).
// A line seen end-on (through the shading point) is the ball at its near end. D is 0 where
// n.h <= 0; a tube entirely there has no specular to normalize, and the factor is 1.
// Self-convergence (lobeFraction 0.02 against 0.005, i.e. panels 4x finer at the peak): see
// tube_energy_normalization/slot.json.
inline double tubeNormalizationTruthWith(const Geometry& g, double alpha, const Vec3& L0, const Vec3& L1, double radius,
                                         double lobeFraction) {
  double R = std::max(radius, 1e-7 * length(L0));
  CapsuleChart ch(L0, L1, R);
  if (ch.endOn) {
    Vec3 nearEnd = length(L0) <= length(L1) ? L0 : L1;
    Geometry gc = makeGeometry(g.n, g.v, nearEnd);
    double sinA = R / length(nearEnd);
    double capSolidAngle = 2.0 * kPi * sinA * sinA / (1.0 + std::sqrt(1.0 - sinA * sinA));
    double capMaxNoH = lights::maxNoHOverCap(gc, sinA);
    if (capMaxNoH <= 0.0) return 1.0;
    return lights::sphereEffectiveD(gc, alpha, sinA) * (kPi * sinA * sinA / capSolidAngle) / ggxD(capMaxNoH, alpha);
  }
  CapsuleQuadrature q(g, alpha, ch, lobeFraction);
  const double tMin = q.tMin, tMax = q.tMax, tPeak = q.tPeak, sPeak = q.sPeak;
  const bool faces = q.faces;
  double integralD = q.integrate([&](const Vec3& l) { return ggxD(std::max(0.0, nohFor(g, l)), alpha); });
  double solidAngle = integrateGraded(
      [&](double t) {
        double s2 = ch.sMax2(t);
        if (s2 <= 0.0) return 0.0;
        Vec3 c1 = L0 + ch.Ld * t;
        double a2 = dot(c1, c1), sm = std::sqrt(s2);
        return ch.h0 * ch.lenD * 2.0 * sm / (a2 * std::sqrt(a2 + s2));
      },
      tMin, tMax, {0.0, 1.0}, 1e-3 * (tMax - tMin));
  // Max n.h over the capsule: 1 if the mirror ray meets it, else on its rim |s| = sMax(t).
  double maxNoH;
  if (faces && tPeak > tMin && tPeak < tMax && ch.sMax2(tPeak) >= sPeak * sPeak) {
    maxNoH = 1.0;
  } else {
    maxNoH = -1.0;
    for (double side : {-1.0, 1.0}) {
      auto negNoH = [&](double t) {
        double s = side * std::sqrt(std::max(0.0, ch.sMax2(t)));
        return -nohFor(g, normalize(ch.point(t, s)));
      };
      double t = scanGoldenMin(negNoH, tMin, tMax, 2048);
      maxNoH = std::max(maxNoH, -negNoH(t));
    }
  }
  if (maxNoH <= 0.0) return 1.0;  // the whole tube is behind every microfacet: no specular
  return integralD / solidAngle / ggxD(maxNoH, alpha);
}

inline double tubeNormalizationTruth(const Geometry& g, double alpha, const Vec3& L0, const Vec3& L1, double radius) {
  return tubeNormalizationTruthWith(g, alpha, L0, L1, radius, 0.02);
}

}  // namespace mb::ref::tubes
