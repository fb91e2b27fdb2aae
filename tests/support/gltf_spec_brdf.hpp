// The glTF specification's BRDF formulas, written out in double for the conformance tests
// (issue 18), independently of shaderlib's references: glTF 2.0 Appendix B (specular_brdf,
// metal_brdf, Schlick), KHR_materials_anisotropy ("Anisotropy": alpha_t, alpha_b, D and V of
// the anisotropic GGX) and KHR_materials_clearcoat ("Layering": fresnel_coat at N_c.V).
#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>

namespace mb::test::gltfspec {

struct V3 {
  double x = 0, y = 0, z = 0;
};
inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator*(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline V3 normalize(V3 a) { return a * (1.0 / std::sqrt(dot(a, a))); }

constexpr double kPi = std::numbers::pi;

// Appendix B: D = alpha^2 chi+(N.H) / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2).
inline double dGgx(double NdotH, double alpha) {
  if (NdotH <= 0) return 0;
  double a2 = alpha * alpha, d = NdotH * NdotH * (a2 - 1) + 1;
  return a2 / (kPi * d * d);
}

// Appendix B: V = G / (4 |N.L| |N.V|) with the height-correlated Smith G, i.e.
// 0.5 / (N.L sqrt((N.V)^2 (1 - alpha^2) + alpha^2) + N.V sqrt((N.L)^2 (1 - alpha^2) + alpha^2)).
inline double vGgx(double NdotL, double NdotV, double alpha) {
  double a2 = alpha * alpha;
  return 0.5 / (NdotL * std::sqrt(NdotV * NdotV * (1 - a2) + a2) + NdotV * std::sqrt(NdotL * NdotL * (1 - a2) + a2));
}

// Appendix B: F = f0 + (1 - f0) (1 - |cos|)^5.
inline double schlick(double f0, double cosine) { return f0 + (1 - f0) * std::pow(1 - std::abs(cosine), 5); }

// KHR_materials_anisotropy: alpha_t = mix(alpha, 1, s^2), alpha_b = alpha.
inline double alphaT(double alpha, double strength) { return alpha + (1 - alpha) * strength * strength; }

// KHR_materials_anisotropy: D = 1 / (pi at ab ((T.H / at)^2 + (B.H / ab)^2 + (N.H)^2)^2).
inline double dGgxAniso(double NdotH, double TdotH, double BdotH, double at, double ab) {
  double s = (TdotH / at) * (TdotH / at) + (BdotH / ab) * (BdotH / ab) + NdotH * NdotH;
  return NdotH > 0 ? 1.0 / (kPi * at * ab * s * s) : 0.0;
}

// KHR_materials_anisotropy: V = 0.5 / (N.L |(at T.V, ab B.V, N.V)| + N.V |(at T.L, ab B.L, N.L)|).
inline double vGgxAniso(double NdotL, double NdotV, double TdotV, double BdotV, double TdotL, double BdotL, double at,
                        double ab) {
  double lv = std::sqrt(at * at * TdotV * TdotV + ab * ab * BdotV * BdotV + NdotV * NdotV);
  double ll = std::sqrt(at * at * TdotL * TdotL + ab * ab * BdotL * BdotL + NdotL * NdotL);
  return 0.5 / (NdotL * lv + NdotV * ll);
}

// A metal's radiance per unit illuminance from a directional light (Appendix B metal_brdf
// = conductor_fresnel(baseColor, specular_brdf) times N.L), one channel.
inline double metalRadiance(double baseColor, V3 n, V3 v, V3 l, double D, double V) {
  V3 h = normalize(v + l);
  return schlick(baseColor, dot(v, h)) * D * V * std::max(dot(n, l), 0.0);
}

}  // namespace mb::test::gltfspec
