// Linearly transformed cosines (Heitz, Dupuy, Hill & Neubelt 2016, "Real-Time Polygonal-Light
// Shading with Linearly Transformed Cosines"), in double: the distribution a 3x3 matrix M makes
// of the clamped cosine D_o(w) = max(w.z, 0) / pi (eq. 1 and 2):
//   D(w) = D_o(w_o) |det M^-1| / |M^-1 w|^3,   w_o = M^-1 w / |M^-1 w|.
// It integrates to 1 over the sphere for every invertible M. The fitter (compiler/ltc)
// chooses M per roughness and view angle so that D approximates the GGX cosine lobe.
#pragma once
#include <array>
#include <cmath>

#include "common/reference.hpp"

namespace mb::ref::ltc {

using Mat3 = std::array<std::array<double, 3>, 3>;  // row-major: m[row][col]

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
