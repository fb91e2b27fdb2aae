#include "energy/half_vector_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mb::energy {
namespace {

HalfVectorAngle fromSin2(double sin2) {
  sin2 = std::clamp(sin2, 0.0, 1.0);
  return {std::sqrt(1.0 - sin2), std::sqrt(sin2)};
}

// exp(-cot^2(theta) / alpha^2), the grazing term of the Ashikhmin distribution; 0 at theta = 0.
double ashikhminGrazing(double cosTheta, double sinTheta, double alpha) {
  if (sinTheta <= 0.0) return 0.0;
  double cot = cosTheta / sinTheta;
  return std::exp(-cot * cot / (alpha * alpha));
}

}  // namespace

const char* mapName(HalfVectorMapKind kind) {
  switch (kind) {
    case HalfVectorMapKind::Cosine:
      return "cosine";
    case HalfVectorMapKind::Ggx:
      return "GGX";
    case HalfVectorMapKind::Beckmann:
      return "Beckmann";
    case HalfVectorMapKind::Charlie:
      return "Charlie";
    case HalfVectorMapKind::Ashikhmin:
      return "Ashikhmin";
  }
  return "?";
}

HalfVectorMap::HalfVectorMap(HalfVectorMapKind kind, double alpha) : kind_(kind), alpha_(alpha) {}

// Closed-form CDFs of D(h)(n.h) integrated over the azimuth and theta' in [0, theta]:
//   cosine  sin^2                      GGX      tan^2 / (alpha^2 + tan^2)
//   Beckmann 1 - exp(-tan^2 / alpha^2)  Charlie  sin^(2 + 1/alpha)
//   Ashikhmin (sin^2 + 4 alpha^2 exp(-cot^2 / alpha^2)) / (1 + 4 alpha^2)
// (each is d/dtheta = 2 pi D cos sin of its D; the Ashikhmin one also shows that the
// 1 / (pi (1 + 4 alpha^2)) normalization makes Int D (n.h) = 1).
double HalfVectorMap::cdf(double theta) const {
  const double c = std::cos(theta), s = std::sin(theta), a2 = alpha_ * alpha_;
  switch (kind_) {
    case HalfVectorMapKind::Cosine:
      return s * s;
    case HalfVectorMapKind::Ggx:
      return s * s / (a2 * c * c + s * s);
    case HalfVectorMapKind::Beckmann:
      return c > 0.0 ? -std::expm1(-(s * s) / (c * c * a2)) : 1.0;
    case HalfVectorMapKind::Charlie:
      return std::pow(s, 2.0 + 1.0 / alpha_);
    case HalfVectorMapKind::Ashikhmin:
      return (s * s + 4.0 * a2 * ashikhminGrazing(c, s, alpha_)) / (1.0 + 4.0 * a2);
  }
  return 0.0;
}

HalfVectorAngle HalfVectorMap::angleAt(double u) const {
  u = std::clamp(u, 0.0, 1.0);
  const double a2 = alpha_ * alpha_;
  switch (kind_) {
    case HalfVectorMapKind::Cosine:
      return fromSin2(u);
    case HalfVectorMapKind::Ggx:
      return fromSin2(a2 * u / ((1.0 - u) + a2 * u));
    case HalfVectorMapKind::Beckmann: {
      double tan2 = -a2 * std::log1p(-u);
      return fromSin2(tan2 / (1.0 + tan2));
    }
    case HalfVectorMapKind::Charlie: {
      // sin = u^(1/(k+2)); cos^2 = 1 - u^(2/(k+2)) via expm1, exact as sin -> 1.
      double e = std::log(u) * 2.0 / (2.0 + 1.0 / alpha_);
      double cos2 = -std::expm1(e);
      return {std::sqrt(std::max(cos2, 0.0)), std::exp(0.5 * e)};
    }
    case HalfVectorMapKind::Ashikhmin: {
      // No closed-form inverse: bisection on the monotone cdf to double precision.
      double lo = 0.0, hi = 0.5 * std::numbers::pi;
      for (int it = 0; it < 64; ++it) {
        double mid = 0.5 * (lo + hi);
        (cdf(mid) < u ? lo : hi) = mid;
      }
      double t = 0.5 * (lo + hi);
      return {std::cos(t), std::sin(t)};
    }
  }
  return {};
}

double HalfVectorMap::density(const HalfVectorAngle& a) const {
  const double c = a.cosTheta, s = a.sinTheta, a2 = alpha_ * alpha_;
  switch (kind_) {
    case HalfVectorMapKind::Cosine:
      return c / std::numbers::pi;
    case HalfVectorMapKind::Ggx: {
      double d = a2 * c * c + s * s;  // (n.h)^2 (alpha^2 - 1) + 1, without cancellation
      return a2 / (std::numbers::pi * d * d) * c;
    }
    case HalfVectorMapKind::Beckmann:
      return std::exp(-(s * s) / (c * c * a2)) / (std::numbers::pi * a2 * c * c * c);
    case HalfVectorMapKind::Charlie: {
      double k = 1.0 / alpha_;
      return (2.0 + k) * std::pow(s, k) / (2.0 * std::numbers::pi) * c;
    }
    case HalfVectorMapKind::Ashikhmin: {
      double term = s > 0.0 ? 4.0 * ashikhminGrazing(c, s, alpha_) / (s * s) / (s * s) : 0.0;
      return (1.0 + term) / (std::numbers::pi * (1.0 + 4.0 * a2)) * c;
    }
  }
  return 0.0;
}

}  // namespace mb::energy
