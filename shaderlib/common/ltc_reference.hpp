// Linearly transformed cosines (Heitz, Dupuy, Hill & Neubelt 2016, "Real-Time Polygonal-Light
// Shading with Linearly Transformed Cosines"), in double: the distribution a 3x3 matrix M makes
// of the clamped cosine D_o(w) = max(w.z, 0) / pi (eq. 1 and 2):
//   D(w) = D_o(w_o) |det M^-1| / |M^-1 w|^3,   w_o = M^-1 w / |M^-1 w|.
// It integrates to 1 over the sphere for every invertible M. The fitter (compiler/ltc)
// chooses M per roughness and view angle so that D approximates the GGX cosine lobe.
#pragma once
#include <array>
#include <algorithm>
#include <cmath>
#include <vector>

#include "common/reference.hpp"

namespace mb::ref::ltc {

using Mat3 = std::array<std::array<double, 3>, 3>;  // row-major: m[row][col]
// The table's M^-1 from its four stored elements (the middle one is 1; docs/models/lights.md).
inline Mat3 minvOf(double m00, double m02, double m20, double m22) {
  return {{{m00, 0, m02}, {0, 1, 0}, {m20, 0, m22}}};
}

inline Vec3 mul(const Mat3& m, const Vec3& v) {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

inline double det(const Mat3& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

inline Mat3 inverse(const Mat3& m) {
  const double d = det(m);
  Mat3 r{};
  r[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / d;
  r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / d;
  r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / d;
  r[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / d;
  r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / d;
  r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / d;
  r[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / d;
  r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / d;
  r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / d;
  return r;
}

// D at the unit direction w, for the inverse matrix minv = M^-1 (eq. 2 with the Jacobian of
// w_o = M^-1 w / |M^-1 w|, eq. 18 of the paper's supplemental derivation).
inline double density(const Mat3& minv, const Vec3& w) {
  const Vec3 o = mul(minv, w);
  const double len2 = dot(o, o);
  const double len = std::sqrt(len2);
  const double cosO = o.z / len;
  if (!(cosO > 0.0)) return 0.0;
  return cosO / kPi * std::abs(det(minv)) / (len2 * len);
}

// The fraction of D above the plane through the origin with unit normal n: the plane maps to
// the plane of normal M^T n under M^-1, and the clamped cosine's share above a plane whose
// normal makes the angle phi with z is (1 + cos phi) / 2 (the cosine's projected disk cut by
// the plane's trace).
inline double fractionAbove(const Mat3& m, const Vec3& n) {
  const Vec3 mt{m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z, m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
                m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z};
  return 0.5 * (1.0 + mt.z / length(mt));
}

}  // namespace mb::ref::ltc

// ---- Integrating D_M over a light (Heitz et al. 2016, section 3.4 and eq. 11).
// D_M over a polygon P is D_o over the polygon M^-1 P, and the clamped cosine's integral over a
// spherical polygon is Lambert's edge sum (Arvo 1995): for the unit vertex directions p_i,
//   I = (1 / 2 pi) sum_i theta_i (p_i x p_i+1).z / |p_i x p_i+1|,  theta_i the angle between them,
// once the polygon is clipped to z >= 0 (D_o is zero below). Lights here are given relative to
// the shading point in world units; polygonIntegral works in the table's frame (n = z, v in the
// x-z plane with v.x >= 0, ltc_fit.hpp), which viewFrame builds.
namespace mb::ref::ltc {

struct ViewFrame {
  Vec3 t1, t2, n;
  Vec3 toLocal(const Vec3& w) const { return {dot(w, t1), dot(w, t2), dot(w, n)}; }
};

// The polygon p (points relative to the origin) clipped to the half-space dot(plane, x) >= 0
// (Sutherland-Hodgman). The plane passes through the origin, so clipping the points clips the
// directions they stand for.
inline std::vector<Vec3> clipToHalfSpace(const std::vector<Vec3>& p, const Vec3& plane) {
  std::vector<Vec3> out;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec3& a = p[i];
    const Vec3& b = p[(i + 1) % p.size()];
    double da = dot(plane, a), db = dot(plane, b);
    if (da >= 0.0) out.push_back(a);
    if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

// Lambert's edge sum over a polygon already above z = 0, in magnitude (either winding).
inline double clampedCosinePolygon(const std::vector<Vec3>& p) {
  double sum = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    Vec3 a = normalize(p[i]), b = normalize(p[(i + 1) % p.size()]);
    Vec3 c = cross(a, b);
    double s = length(c);
    if (s > 0.0) sum += std::atan2(s, dot(a, b)) * c.z / s;
  }
  return std::abs(sum) / (2.0 * kPi);
}

// Int over the polygon of D_M (M^-1 = minv) in the frame fr, above the surface's horizon;
// world-space vertices relative to the shading point. With minv the identity it is
// Int (n.l)+ dw / pi, the diffuse form factor.
// Two clips: first to the horizon n.l >= 0, because the lobe D_M stands for is zero below it
// while D_M is not (its support is the half-space (M^-1 w).z > 0, tilted against the horizon);
// then to that support. Heitz et al. clip only the second, which leaves the light below the
// horizon in the integral: far too bright for lights partly below it (an early run of
// bench/bench_area_lights.cpp without the first clip; that variant is not kept).
inline double polygonIntegral(const Mat3& minv, const ViewFrame& fr, const std::vector<Vec3>& world) {
  std::vector<Vec3> p;
  p.reserve(world.size());
  for (const Vec3& w : world) p.push_back(fr.toLocal(w));
  p = clipToHalfSpace(p, Vec3{0, 0, 1});
  for (Vec3& q : p) q = mul(minv, q);
  p = clipToHalfSpace(p, Vec3{0, 0, 1});
  return p.size() < 3 ? 0.0 : clampedCosinePolygon(p);
}

// ---- The light shapes as polygons of directions.
// A circle becomes a regular polygon whose area equals the circle's: its vertices sit at
// radius * polygonAreaScale(k); the remaining difference is of second order in the light's
// angular size (docs/models/lights.md measures it).
inline double polygonAreaScale(int k) { return std::sqrt(2.0 * kPi / (k * std::sin(2.0 * kPi / k))); }
// The radius at which a regular k-gon's mean width (its perimeter over pi, Cauchy) is the
// circle's: what a capsule's sides take from its end caps (tubePolygon).
inline double polygonWidthScale(int k) { return kPi / (k * std::sin(kPi / k)); }

inline constexpr int kLtcCircleVertices = 8;
// A capsule's end caps take twice as many: the width of its sides, which depends on the
// capsule's orientation, is then 0.987 to 1.006 of the circle's instead of 0.948 to 1.026
// (at polygonWidthScale; docs/models/lights.md).
inline constexpr int kLtcTubeCapVertices = 16;

// A rectangle light with centre c and half-edge vectors ex, ey, emitting on the side of
// ex x ey. Seen from behind (or edge-on) it sends nothing: an empty polygon.
inline std::vector<Vec3> rectPolygon(const Vec3& c, const Vec3& ex, const Vec3& ey) {
  if (!(dot(cross(ex, ey), c) < 0.0)) return {};
  return {c - ex - ey, c + ex - ey, c + ex + ey, c - ex + ey};
}

// A disk (or ellipse) light with centre c and semi-axis vectors ex, ey, one-sided as the
// rectangle: the area-matched regular polygon.
inline std::vector<Vec3> diskPolygon(const Vec3& c, const Vec3& ex, const Vec3& ey, int k = kLtcCircleVertices,
                                     double s = 0.0) {
  if (!(dot(cross(ex, ey), c) < 0.0)) return {};
  std::vector<Vec3> p;
  if (s == 0.0) s = polygonAreaScale(k);
  for (int i = 0; i < k; ++i) {
    double phi = 2.0 * kPi * i / k;
    p.push_back(c + (ex * std::cos(phi) + ey * std::sin(phi)) * s);
  }
  return p;
}

// The unit vectors e1, e2 completing the unit c to an orthonormal frame: Duff et al. 2017
// ("Building an Orthonormal Basis, Revisited"), the formula of lights.glsl's
// mb_orthonormal_basis, so that the GPU's polygon has the same orientation about c.
inline void perpendicularPair(const Vec3& c, Vec3& e1, Vec3& e2) {
  double s = c.z >= 0.0 ? 1.0 : -1.0;
  double a = -1.0 / (s + c.z);
  double b = c.x * c.y * a;
  e1 = {1.0 + s * c.x * c.x * a, s * b, -s * c.x};
  e2 = {b, s + c.y * c.y * a, -c.y};
}

// A planar (rectangle or disk) light centred at c, of half-edges (semi-axes) hx and hy along the
// pair perpendicular to c turned about it by `turn`, the second tilted by `tilt` from facing
// the shading point, wound so that ex x ey points back at the point (it faces the point): how
// the bench and the tests draw their rectangles and disks.
struct PlanarLight {
  Vec3 c, ex, ey;
};
inline PlanarLight facingPlanarLight(const Vec3& c, double hx, double hy, double turn, double tilt) {
  Vec3 e1, e2;
  perpendicularPair(c, e1, e2);
  Vec3 u = e1 * std::cos(turn) + e2 * std::sin(turn), w = cross(c, u);
  Vec3 ey = (w * std::cos(tilt) + c * std::sin(tilt)) * hy;
  Vec3 ex = u * hx;
  if (!(dot(cross(ex, ey), c) < 0.0)) ex = ex * -1.0;
  return {c, ex, ey};
}

// t1 along v's component in the tangent plane; where v is (nearly) the normal any tangent will
// do, the table's lobe being symmetric about n there (common/ltc.glsl, the same rule).
inline ViewFrame viewFrame(const Vec3& n, const Vec3& v) {
  Vec3 t = v - n * dot(n, v);
  double len = length(t);
  Vec3 t1, unused;
  if (len > 1e-6)
    t1 = t / len;
  else
    perpendicularPair(n, t1, unused);
  return {t1, cross(n, t1), n};
}

// The sin of the angular radius of a ball of radius R at distance d; inside the ball (and at
// its centre) the bound the representative-point bricks use too (standard_lights.glsl).
inline constexpr double kLtcMaxSinAlpha = 0.95;
inline double ballSinAlpha(double d, double R) { return d > 0.0 ? std::min(R / std::max(d, R), kLtcMaxSinAlpha) : 0.0; }

// A sphere light: the disk that faces the shading point and subtends exactly the sphere's cap
// (its rim is the cap's rim, at unit distance: centre c cos a, radius sin a). D_M integrates
// over directions, so the disk stands for the sphere exactly (Heitz & Hill 2017 shade spheres
// as such disks); only the polygon's approximation of the circle remains.
inline std::vector<Vec3> spherePolygon(const Vec3& toCenter, double R, const Vec3& n, int k = kLtcCircleVertices,
                                       double scale = 0.0) {
  double d = length(toCenter);
  Vec3 c = d > 0.0 ? toCenter / d : n;
  double sinA = ballSinAlpha(d, R), cosA = std::sqrt(1.0 - sinA * sinA);
  Vec3 e1, e2;
  perpendicularPair(c, e1, e2);
  // Wound so that ex x ey points back at the shading point (a disk facing it).
  return diskPolygon(c * cosA, e2 * sinA, e1 * sinA, k, scale);
}

// A tube (capsule) light, segment L0 -> L1 of radius R: its silhouette seen from the shading
// point, the spherical convex hull of its two end balls' caps. Each cap is a regular k-gon
// oriented as the sphere light's (spherePolygon), at the radius that gives it the circle's mean
// width rather than its area: a capsule's sides, tangent to the caps, take their width from
// the k-gons' outermost vertices, and the area-matched 8-gon made tubes 2.6 % too bright at the
// median (docs/models/lights.md). The hull is taken of their 2k vertices
// by gift wrapping on the sphere (Jarvis 1973): from the vertex farthest against e1 of the ends'
// mean direction, each next vertex is the one that leaves every other on the left of the great
// circle through both. The hull moves continuously with the ends: seen end-on, the near cap
// contains the far one and the hull is the near cap's polygon whichever way the axis tilts.
// (Half caps joined across the axis, the construction this replaced, jump there: the side
// across the axis is undefined end-on, and fp32 rounding on an NVIDIA H200 picked another side
// than the reference, 40 % apart: docs/devices.md.) Needs every vertex in one open hemisphere,
// which holds unless the shading point is (nearly) inside the capsule.
inline std::vector<Vec3> tubePolygon(const Vec3& L0, const Vec3& L1, double R, const Vec3& n,
                                     int k = kLtcTubeCapVertices) {
  std::vector<Vec3> pts = spherePolygon(L0, R, n, k, polygonWidthScale(k));
  std::vector<Vec3> far = spherePolygon(L1, R, n, k, polygonWidthScale(k));
  if (pts.empty() || far.empty()) return {};  // no radius: a line has no solid angle
  pts.insert(pts.end(), far.begin(), far.end());
  double d0 = length(L0), d1 = length(L1);
  Vec3 mid = (d0 > 0.0 ? L0 / d0 : n) + (d1 > 0.0 ? L1 / d1 : n);
  Vec3 m = length(mid) > 0.0 ? normalize(mid) : n;
  Vec3 e1, e2;
  perpendicularPair(m, e1, e2);
  auto same = [](const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; };
  const int count = static_cast<int>(pts.size());
  int cur = 0;
  for (int j = 1; j < count; ++j)
    if (dot(normalize(pts[j]), e1) < dot(normalize(pts[cur]), e1)) cur = j;
  std::vector<bool> seen(count, false);
  std::vector<Vec3> hull;
  while (true) {
    const Vec3& p = pts[cur];
    hull.push_back(p);
    seen[cur] = true;
    int next = -1;
    for (int j = 0; j < count; ++j) {
      const Vec3& q = pts[j];
      if (same(q, p)) continue;
      if (next < 0) {
        next = j;
        continue;
      }
      const Vec3& best = pts[next];
      // q right of p -> best is the better next; the determinant [p, best, q] from the
      // differences, as common/ltc.glsl computes it.
      if (dot(p, cross(best - p, q - p)) < 0.0) next = j;
    }
    if (next < 0 || seen[next]) break;  // closed, or stopped where choices became inconsistent
    cur = next;
  }
  return hull;
}

// ---- The LTC as a control variate (sphere_ltc_cv, tube_ltc_cv, rect_ltc_cv, disk_ltc_cv).
// The LTC alone is off where the fitted D_M departs from the lobe it stands for: a few percent
// at the lobe's peak, and in its tails (D_M ends at its support plane, and does not vanish at
// the horizon as the lobe's n.l does) by up to 100 % of a light that only the tails see
// (docs/models/lights.md). What the integral misses is Int (lobe - norm D_M) over the light, a
// residual that is small wherever the fit is good. It is integrated by a deterministic
// quadrature in the LTC's own space: with w = M w_o / |M w_o| (the substitution of Heitz et al.
// 2016, section 3.4) the residual over the light is
//   Int over M^-1 P of ( lobe(w) J(w_o) - norm D_o(w_o) ) dw_o,  J = dw / dw_o = |det M| / |M w_o|^3,
// and lobe J follows norm D_o, a clamped cosine, wherever the fit is good: the lobe's peak,
// as narrow as alpha about the mirror direction, is spread over the cosine's whole hemisphere.
// A quadrature of the residual in the light's own directions samples that peak at a few points,
// and one landing on it carries a value up to 1 / alpha^2 larger than the integral: in fp32,
// whose directions carry ~1e-6 rad, that made the result 60-80 % off its double at alpha < 0.04
// (validate, 50,000 samples; docs/models/lights.md), and the double itself 4.7-11 % off the
// brute force at the 95th percentile for roughness < 0.1. The polygon M^-1 P is split at D_M's
// support plane z = 0 (where D_o has its kink); each part is covered by triangles fanned from its
// vertices' mean direction, each split once into its four midpoint children, each child its
// solid angle (Van Oosterom & Strackee 1983) times the mean at three interior points, the
// planar triangle's degree-2 rule (barycentric 2/3, 1/6, 1/6).
inline constexpr double kFanPoint = 2.0 / 3.0, kFanOther = 1.0 / 6.0;

// One spherical triangle a, b, c (unit vectors): its solid angle times the mean of f at the
// three points, or the sum over its four midpoint children `levels` times over.
template <class F>
double triangleQuadrature(const Vec3& a, const Vec3& b, const Vec3& c, F& f, int levels) {
  if (levels > 0) {
    Vec3 ab = normalize(a + b), bc = normalize(b + c), ca = normalize(c + a);
    return triangleQuadrature(a, ab, ca, f, levels - 1) + triangleQuadrature(ab, b, bc, f, levels - 1) +
           triangleQuadrature(ca, bc, c, f, levels - 1) + triangleQuadrature(ab, bc, ca, f, levels - 1);
  }
  double omega = 2.0 * std::atan2(std::abs(dot(a, cross(b, c))), 1.0 + dot(a, b) + dot(b, c) + dot(c, a));
  return omega *
         (f(normalize(a * kFanPoint + b * kFanOther + c * kFanOther)) +
          f(normalize(b * kFanPoint + a * kFanOther + c * kFanOther)) +
          f(normalize(c * kFanPoint + a * kFanOther + b * kFanOther))) /
         3.0;
}

template <class F>
double fanQuadrature(const std::vector<Vec3>& polygon, F f, int levels = 0) {
  if (polygon.size() < 3) return 0.0;
  Vec3 centre{0, 0, 0};
  for (const Vec3& p : polygon) centre = centre + normalize(p);
  centre = normalize(centre);
  double sum = 0.0;
  for (size_t k = 0; k < polygon.size(); ++k)
    sum += triangleQuadrature(centre, normalize(polygon[k]), normalize(polygon[(k + 1) % polygon.size()]), f, levels);
  return sum;
}

// The standard model's specular lobe (F = 1) the table was fitted to, at the unit direction l in
// the table's frame (n = z): GGX D (Walter et al. 2007) times the exact height-correlated Smith
// V (Heitz 2014 eq. 99) times n.l; 0 below the horizon.
inline double ggxLobeLocal(const Vec3& v, double alpha, const Vec3& l) {
  if (!(l.z > 0.0)) return 0.0;
  Vec3 h = normalize(v + l);
  double a2 = alpha * alpha, NoH = h.z, NoV = std::max(v.z, kMinNoV), NoL = l.z;
  double d = NoH * NoH * (a2 - 1.0) + 1.0;
  double D = a2 / (kPi * d * d);
  double V = 0.5 / (NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2) + NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2));
  return D * V * NoL;
}

// The standard model's sheen lobe (sheenColor = 1) the sheen table was fitted to
// (shaderlib/ltc/charlie.json): Charlie D(h) = (2 + 1/alpha) sin^(1/alpha)(theta_h) / (2 pi)
// (Estevez & Kulla 2017, eq. 2) times V = 1 / (4 (n.l + n.v - n.l n.v)) (Neubelt & Pettineo
// 2013) times n.l; 0 below the horizon. sin^(1/alpha) from sin^2 = (H.x^2 + H.y^2) / |H|^2 of
// the unnormalized half vector, exact where theta_h nears 90 degrees (D's peak).
inline double charlieD(double sin2, double alpha) {
  return (2.0 + 1.0 / alpha) * std::pow(sin2, 0.5 / alpha) / (2.0 * kPi);
}
inline double charlieLobeLocal(const Vec3& v, double alpha, const Vec3& l) {
  if (!(l.z > 0.0)) return 0.0;
  const Vec3 H = v + l;
  const double HH = dot(H, H);
  if (!(HH > 0.0)) return 0.0;
  const double D = charlieD((H.x * H.x + H.y * H.y) / HH, alpha);
  const double NoV = std::max(v.z, kMinNoV), NoL = l.z;
  return D * NoL / (4.0 * (NoL + NoV - NoL * NoV));
}

// Which lobe a table, a brick's residual and a ground truth stand for.
enum class LobeKind { Ggx, Charlie };
inline double lobeLocal(LobeKind kind, const Vec3& v, double alpha, const Vec3& l) {
  return kind == LobeKind::Charlie ? charlieLobeLocal(v, alpha, l) : ggxLobeLocal(v, alpha, l);
}

// ---- The brute-force lobe integral over a polygonal light (ground truth of the rectangle and
// disk bricks, mb_bench_area_lights): the fan of the horizon-clipped polygon's spherical
// triangles, each subdivided adaptively: split in four at its edge midpoints while the
// children's degree-2 estimates (triangleQuadrature) differ from the parent's by more than the
// tolerance (halved per level), or while it holds the mirror direction and is wider than
// alpha / 4 (a sharp peak between the sample points would look like no peak), to depth 18.
// Made 10 times stricter it moves by at most 2.4e-7 (docs/models/lights.md).
class AdaptiveLobeFan {
 public:
  AdaptiveLobeFan(const Vec3& v, double alpha, LobeKind kind = LobeKind::Ggx)
      : v_(v), alpha_(alpha), kind_(kind), mirror_(Vec3{-v.x, -v.y, v.z}) {}
  double integrate(const std::vector<Vec3>& local, double tol) {
    if (local.size() < 3) return 0.0;
    Vec3 centre{0, 0, 0};
    for (const Vec3& p : local) centre = centre + normalize(p);
    centre = normalize(centre);
    double sum = 0.0;
    for (size_t k = 0; k < local.size(); ++k) {
      Vec3 b = normalize(local[k]), c = normalize(local[(k + 1) % local.size()]);
      sum += refine(centre, b, c, triangle(centre, b, c), tol, 0);
    }
    return sum;
  }

 private:
  double triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    auto f = [this](const Vec3& l) { return lobeLocal(kind_, v_, alpha_, l); };
    return triangleQuadrature(a, b, c, f, 0);
  }
  // GGX's peak about the mirror direction; the sheen's lies along the horizon of h, which the
  // tolerance's refinement follows.
  bool holdsPeak(const Vec3& a, const Vec3& b, const Vec3& c) const {
    if (kind_ != LobeKind::Ggx) return false;
    double s0 = dot(cross(a, b), mirror_), s1 = dot(cross(b, c), mirror_), s2 = dot(cross(c, a), mirror_);
    bool inside = (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
    return inside && std::max({length(a - b), length(b - c), length(c - a)}) > 0.25 * alpha_;
  }
  double refine(const Vec3& a, const Vec3& b, const Vec3& c, double estimate, double tol, int depth) {
    Vec3 ab = normalize(a + b), bc = normalize(b + c), ca = normalize(c + a);
    double k0 = triangle(a, ab, ca), k1 = triangle(ab, b, bc), k2 = triangle(ca, bc, c), k3 = triangle(ab, bc, ca);
    double sum = k0 + k1 + k2 + k3;
    if (depth >= 18 || (depth >= 3 && std::abs(sum - estimate) <= tol && !holdsPeak(a, b, c))) return sum;
    return refine(a, ab, ca, k0, tol * 0.5, depth + 1) + refine(ab, b, bc, k1, tol * 0.5, depth + 1) +
           refine(ca, bc, c, k2, tol * 0.5, depth + 1) + refine(ab, bc, ca, k3, tol * 0.5, depth + 1);
  }
  Vec3 v_;
  double alpha_;
  LobeKind kind_;
  Vec3 mirror_;  // reflect(-v, z)
};

// Int of the lobe (F = 1) over the local, horizon-clipped polygon, to `tol` absolute.
inline double lobeIntegralAdaptive(const std::vector<Vec3>& local, const Vec3& v, double alpha, double tol,
                                   LobeKind kind = LobeKind::Ggx) {
  return AdaptiveLobeFan(v, alpha, kind).integrate(local, tol);
}

// The same over a light polygon `world` (points relative to the shading point) above the
// horizon of n, to 1e-7 of the light's irradiance (the lobe's integral is at most a few times
// it): the ground truth of the rectangle and disk bricks.
inline double lobeOverPolygon(const Vec3& n, const Vec3& v, double alpha, const std::vector<Vec3>& world,
                              LobeKind kind = LobeKind::Ggx) {
  const ViewFrame fr = viewFrame(n, v);
  std::vector<Vec3> local;
  for (const Vec3& w : world) local.push_back(fr.toLocal(w));
  local = clipToHalfSpace(local, Vec3{0, 0, 1});
  return lobeIntegralAdaptive(local, fr.toLocal(v), alpha, 1e-7 * kPi * clampedCosinePolygon(local), kind);
}

// The lobe's integral (F = 1) over a rectangle, or a disk as its 256-gon, about n with view v,
// to 1e-7 of the light's irradiance Int (n.l)+ dw, which it returns beside it (both 0 for a
// light below the horizon): what the model's planar lights are measured against.
struct PlanarTruth {
  double lobe = 0, irradiance = 0;
};
inline PlanarTruth planarLobeTruth(const Vec3& n, const Vec3& v, double alpha, const PlanarLight& light, bool disk,
                                   LobeKind kind = LobeKind::Ggx) {
  const ViewFrame fr = viewFrame(n, v);
  std::vector<Vec3> local;
  for (const Vec3& p : disk ? diskPolygon(light.c, light.ex, light.ey, 256) : rectPolygon(light.c, light.ex, light.ey))
    local.push_back(fr.toLocal(p));
  local = clipToHalfSpace(local, Vec3{0, 0, 1});
  if (local.size() < 3) return {};
  PlanarTruth t;
  t.irradiance = kPi * clampedCosinePolygon(local);
  t.lobe = lobeIntegralAdaptive(local, fr.toLocal(v), alpha, 1e-7 * t.irradiance, kind);
  return t;
}

// The residual's integrand in the LTC's space at the unit w_o (M = inverse of minv, detM its
// determinant): the lobe at w = M w_o / |M w_o| times the Jacobian, less norm D_o(w_o).
inline double warpedResidual(const Mat3& m, double detM, double norm, const Vec3& v, double alpha, const Vec3& o,
                             LobeKind kind = LobeKind::Ggx) {
  const Vec3 w = mul(m, o);
  const double len = length(w);
  return lobeLocal(kind, v, alpha, w / len) * std::abs(detM) / (len * len * len) - norm * std::max(o.z, 0.0) / kPi;
}

// Int over the light polygon `world` of the lobe (F = 1) above the horizon: norm times the LTC
// integral plus the residual's quadrature in the LTC's space (above), whose triangles are split
// `levels` times (the bricks: once).
inline constexpr int kResidualLevels = 1;
inline double polygonSpecularWithResidual(const Mat3& minv, double norm, double alpha, const ViewFrame& fr,
                                          const Vec3& v, const std::vector<Vec3>& world, int levels = kResidualLevels,
                                          LobeKind kind = LobeKind::Ggx) {
  std::vector<Vec3> local;
  local.reserve(world.size());
  for (const Vec3& w : world) local.push_back(fr.toLocal(w));
  local = clipToHalfSpace(local, Vec3{0, 0, 1});
  if (local.size() < 3) return 0.0;
  const Vec3 vl = fr.toLocal(v);
  const Mat3 m = inverse(minv);
  const double detM = det(m);
  std::vector<Vec3> mapped;
  for (const Vec3& q : local) mapped.push_back(mul(minv, q));
  const std::vector<Vec3> inside = clipToHalfSpace(mapped, Vec3{0, 0, 1});
  const std::vector<Vec3> outside = clipToHalfSpace(mapped, Vec3{0, 0, -1});
  auto residual = [&](const Vec3& o) { return warpedResidual(m, detM, norm, vl, alpha, o, kind); };
  const double ltc = inside.size() < 3 ? 0.0 : clampedCosinePolygon(inside);
  const double sum = fanQuadrature(inside, residual, levels) + fanQuadrature(outside, residual, levels);
  // Between 0 and the lobe's integral over the whole hemisphere, norm (common/ltc.glsl).
  return std::clamp(norm * ltc + sum, 0.0, norm);
}

}  // namespace mb::ref::ltc
