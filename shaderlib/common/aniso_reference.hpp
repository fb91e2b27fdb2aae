// The tangent frame of the anisotropic bricks in double (see common/aniso.glsl for the
// shader side and why the bricks orthonormalize the interpolated tangent themselves).
// Gram-Schmidt: t_perp = t - (t.n) n, T = t_perp / |t_perp|, B = n x T. A tangent with
// |t_perp|^2 <= 1e-12 |t|^2 (parallel to n, or zero) has no usable direction; the frame then
// takes the deterministic basis of Duff et al. 2017 (JCGT 6(1), listing 3), as the shader does.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>

#include "common/reference.hpp"

namespace mb::ref {

struct AnisoFrame {
  Vec3 t, b, n;  // orthonormal, right-handed: b = n x t
  // Coordinates of w in the frame: (t.w, b.w, n.w).
  Vec3 local(const Vec3& w) const { return {dot(t, w), dot(b, w), dot(n, w)}; }
};

inline Vec3 duffTangent(const Vec3& n) {
  double sign = n.z >= 0.0 ? 1.0 : -1.0;
  double a = -1.0 / (sign + n.z);
  return {1.0 + sign * n.x * n.x * a, sign * n.x * n.y * a, -sign * n.x};
}

// n must be unit length (Geometry::n is).
inline AnisoFrame anisoFrame(const Vec3& n, const Vec3& tangent) {
  Vec3 perp = tangent - n * dot(tangent, n);
  Vec3 t = dot(perp, perp) > 1e-12 * dot(tangent, tangent) ? normalize(perp) : duffTangent(n);
  return {t, cross(n, t), n};
}

}  // namespace mb::ref

namespace mb::ref {

// Spherical-coordinate terms of a unit direction in the shading frame, as pbrt-v4 writes
// them (util/vecmath.h): cos theta is the given (clamped) n.w, and phi is the azimuth of the
// direction's tangent-plane part; phi = 0 where sin theta = 0 (pbrt's convention).
struct LocalAngles {
  double cos2Theta, sin2Theta, tan2Theta, cos2Phi, sin2Phi;
};

inline LocalAngles localAngles(const AnisoFrame& f, const Vec3& w, double cosTheta) {
  LocalAngles a;
  a.cos2Theta = cosTheta * cosTheta;
  a.sin2Theta = std::max(0.0, 1.0 - a.cos2Theta);
  a.tan2Theta = a.cos2Theta == 0.0 ? std::numeric_limits<double>::infinity() : a.sin2Theta / a.cos2Theta;
  Vec3 p = f.local(w);
  double sinTheta = std::sqrt(p.x * p.x + p.y * p.y);
  double cosPhi = sinTheta == 0.0 ? 1.0 : std::clamp(p.x / sinTheta, -1.0, 1.0);
  double sinPhi = sinTheta == 0.0 ? 0.0 : std::clamp(p.y / sinTheta, -1.0, 1.0);
  a.cos2Phi = cosPhi * cosPhi;
  a.sin2Phi = sinPhi * sinPhi;
  return a;
}

}  // namespace mb::ref
