// Exact microfacet and Fresnel quantities in double, shared by the references and ground
// truths of several bricks. Each function is written from the paper's definition in its most
// direct form (pbrt-v4 style), with the edge cases guarded explicitly.
#pragma once
#include <cmath>
#include <limits>

#include "common/reference.hpp"

namespace mb::ref {

// tan^2 of the angle whose cosine is cosTheta (cosTheta in [0, 1]); +inf at cosTheta = 0.
inline double tan2FromCos(double cosTheta) {
  double cos2 = cosTheta * cosTheta;
  if (cos2 == 0.0) return std::numeric_limits<double>::infinity();
  return std::max(0.0, 1.0 - cos2) / cos2;
}

// Smith Lambda of the isotropic GGX distribution (Heitz 2014, "Understanding the
// Masking-Shadowing Function in Microfacet-Based BRDFs", eq. 72; pbrt-v4
// TrowbridgeReitzDistribution::Lambda):  Lambda = (-1 + sqrt(1 + alpha^2 tan^2)) / 2.
inline double smithGgxLambda(double cosTheta, double alpha) {
  double tan2 = tan2FromCos(cosTheta);
  if (std::isinf(tan2)) return std::numeric_limits<double>::infinity();
  return (-1.0 + std::sqrt(1.0 + alpha * alpha * tan2)) / 2.0;
}

// Exact height-correlated Smith visibility for GGX (Heitz 2014, eq. 99):
//   G2 = 1 / (1 + Lambda(v) + Lambda(l)),   V = G2 / (4 n.l n.v).
// At n.l = 0 (or n.v = 0) G2 -> 0 and V has a finite limit: Lambda(l) ~ alpha/(2 n.l), so
// V -> 1 / (2 alpha n.v); both are handled explicitly.
inline double smithGgxCorrelatedV(double NoV, double NoL, double alpha) {
  if (NoL == 0.0 && NoV == 0.0) return std::numeric_limits<double>::infinity();
  if (NoL == 0.0) return 1.0 / (2.0 * alpha * NoV);
  if (NoV == 0.0) return 1.0 / (2.0 * alpha * NoL);
  double g2 = 1.0 / (1.0 + smithGgxLambda(NoV, alpha) + smithGgxLambda(NoL, alpha));
  return g2 / (4.0 * NoL * NoV);
}

// Smith Lambda of the anisotropic GGX distribution (Heitz 2014, eq. 86): alpha is replaced
// by the projected roughness alpha_o = sqrt(cos^2(phi) at^2 + sin^2(phi) ab^2), i.e.
//   alpha_o^2 tan^2(theta) = ((t.w)^2 at^2 + (b.w)^2 ab^2) / (n.w)^2.
inline double smithGgxAnisoLambda(double NoW, double ToW, double BoW, double at, double ab) {
  if (NoW == 0.0) return std::numeric_limits<double>::infinity();
  double a2tan2 = (ToW * ToW * at * at + BoW * BoW * ab * ab) / (NoW * NoW);
  return (-1.0 + std::sqrt(1.0 + a2tan2)) / 2.0;
}

// Exact unpolarized Fresnel reflectance of a dielectric interface with relative index of
// refraction eta (> 0), for the cosine of the incident angle cosI in [0, 1] (Born & Wolf;
// pbrt-v4 FrDielectric). Total internal reflection returns 1.
inline double fresnelDielectric(double cosI, double eta) {
  if (std::isinf(eta)) return 1.0;
  double sin2I = std::max(0.0, 1.0 - cosI * cosI);
  double sin2T = sin2I / (eta * eta);
  if (sin2T >= 1.0) return 1.0;
  double cosT = std::sqrt(1.0 - sin2T);
  double rParallel = (eta * cosI - cosT) / (eta * cosI + cosT);
  double rPerpendicular = (cosI - eta * cosT) / (cosI + eta * cosT);
  return (rParallel * rParallel + rPerpendicular * rPerpendicular) / 2.0;
}

// The index of refraction whose normal-incidence reflectance is f0 (in [0, 1]):
//   f0 = ((eta - 1) / (eta + 1))^2  =>  eta = (1 + sqrt f0) / (1 - sqrt f0); f0 = 1 -> +inf.
inline double etaFromF0(double f0) {
  double s = std::sqrt(std::max(0.0, f0));
  if (s >= 1.0) return std::numeric_limits<double>::infinity();
  return (1.0 + s) / (1.0 - s);
}

// Exact Fresnel of the dielectric implied by f0, per channel: the ground truth of the
// Schlick family (which stands in for it with f90 = 1).
inline Vec3 fresnelDielectricFromF0(double cosI, const Vec3& f0) {
  return {fresnelDielectric(cosI, etaFromF0(f0.x)), fresnelDielectric(cosI, etaFromF0(f0.y)),
          fresnelDielectric(cosI, etaFromF0(f0.z))};
}

}  // namespace mb::ref
