#include "energy/albedo_quadrature.hpp"

#include <algorithm>
#include <cmath>

#include "common/ibl_reference.hpp"

namespace mb::energy {
namespace {

constexpr double kPi = ref::kPi;

// Gauss-Legendre, 8 nodes on [-1, 1] (shared with the DFG reference quadrature).
const ref::detail_ibl::GaussLegendre<8>& gauss8() {
  static const ref::detail_ibl::GaussLegendre<8> g;
  return g;
}

// Calls fn(x, w) for a composite 8-node Gauss-Legendre rule of `panels` panels on [a, b].
template <class Fn>
void compositeGauss(double a, double b, int panels, Fn&& fn) {
  const auto& g = gauss8();
  const double width = (b - a) / panels;
  for (int p = 0; p < panels; ++p) {
    double mid = a + (p + 0.5) * width;
    for (int i = 0; i < 8; ++i) fn(mid + 0.5 * width * g.x[i], 0.5 * width * g.w[i]);
  }
}

// 8-node Gauss-Legendre on [a, b] for an integrand with a square-root endpoint at a
// (sqrtAtA) or at b (sqrtAtB): u = a + (b - a) t^2 (or b - (b - a) t^2) makes it smooth in t.
template <class Fn>
void gaussPanel(double a, double b, bool sqrtAtA, bool sqrtAtB, Fn&& fn) {
  const auto& g = gauss8();
  for (int i = 0; i < 8; ++i) {
    double t = 0.5 * (1.0 + g.x[i]), wt = 0.5 * g.w[i];
    if (sqrtAtA) {
      fn(a + (b - a) * t * t, wt * 2.0 * t * (b - a));
    } else if (sqrtAtB) {
      fn(b - (b - a) * t * t, wt * 2.0 * t * (b - a));
    } else {
      fn(a + (b - a) * t, wt * (b - a));
    }
  }
}

struct NodeSink {
  const ref::Vec3& v;
  const HalfVectorMap& map;
  std::vector<AlbedoNode>& out;
  // One half vector at (angle, phi) with measure wu * wphi in (u, phi).
  void add(const HalfVectorAngle& a, double phi, double wu, double wphi) const {
    ref::Vec3 h{a.sinTheta * std::cos(phi), a.sinTheta * std::sin(phi), a.cosTheta};
    double VoH = ref::dot(v, h);
    ref::Vec3 l = h * (2.0 * VoH) - v;
    double NoL = l.z, pdf = map.density(a);
    // n.l <= 0 only by rounding at the horizon; pdf == 0 only where the map's u-measure
    // underflowed to zero (a Charlie lobe far from its peak), which carries no weight.
    if (NoL <= 0.0 || VoH <= 0.0 || !(pdf > 0.0)) return;
    // d(omega_h) = du dphi / (2 pi pdf(h)), d(omega_l) = 4 (v.h) d(omega_h).
    double weight = wu * wphi * 4.0 * VoH * NoL / (2.0 * kPi * pdf);
    out.push_back({ref::normalize(l), weight});
  }
};

// Panel breakpoints in u on [u0, u1]: uniform in u (importance), uniform in theta_h (so
// that no panel spans a wide angle where the map is steep, e.g. Charlie's sin^(1/alpha)),
// and the extra points given; sorted, without empty panels.
std::vector<double> breakpoints(const HalfVectorMap& map, double theta0, double theta1, double u0, double u1,
                                int panels, std::vector<double> extra = {}) {
  std::vector<double> b = std::move(extra);
  for (int k = 0; k <= panels; ++k) {
    b.push_back(u0 + (u1 - u0) * k / panels);
    b.push_back(map.cdf(theta0 + (theta1 - theta0) * k / panels));
  }
  for (double& x : b) x = std::clamp(x, u0, u1);
  std::sort(b.begin(), b.end());
  b.erase(std::unique(b.begin(), b.end()), b.end());
  return b;
}

}  // namespace

std::vector<AlbedoNode> albedoNodes(const ref::Vec3& v, const HalfVectorMap& map, const QuadratureResolution& res) {
  std::vector<AlbedoNode> out;
  NodeSink sink{v, map, out};
  const double cosV = v.z, sinV = std::sqrt(v.x * v.x + v.y * v.y);
  const double thetaV = std::atan2(sinV, cosV);
  const double thetaFull = 0.25 * kPi - 0.5 * thetaV, thetaNone = 0.25 * kPi + 0.5 * thetaV;
  const double uFull = map.cdf(thetaFull), uNone = map.cdf(thetaNone);

  // Every azimuth: trapezoid over the full period.
  const int ringNodes = 8 * res.phiPanels;
  std::vector<double> a = breakpoints(map, 0.0, thetaFull, 0.0, uFull, res.thetaPanels);
  for (size_t p = 0; p + 1 < a.size(); ++p)
    gaussPanel(a[p], a[p + 1], false, false, [&](double u, double wu) {
      HalfVectorAngle h = map.angleAt(u);
      for (int j = 0; j < ringNodes; ++j) sink.add(h, -kPi + 2.0 * kPi * j / ringNodes, wu, 2.0 * kPi / ringNodes);
    });

  // Partial azimuth [-phiMax, phiMax], phiMax = acos(kappa), kappa = -cot(theta_v) cot(2 theta_h).
  if (!(uNone > uFull) || sinV <= 0.0) return out;
  // Also break where kappa = -cos(pi k / P): at grazing v, phiMax falls from pi to pi/2 within
  // ~1/tan(theta_v) of thetaFull (and from pi/2 to 0 near thetaNone).
  std::vector<double> extra;
  for (int k = 1; k < res.thetaPanels; ++k) {
    double cot2 = std::cos(kPi * k / res.thetaPanels) * sinV / cosV;
    extra.push_back(map.cdf(0.5 * std::atan2(1.0, cot2)));
  }
  std::vector<double> b = breakpoints(map, thetaFull, thetaNone, uFull, uNone, res.thetaPanels, extra);
  for (size_t p = 0; p + 1 < b.size(); ++p)
    gaussPanel(b[p], b[p + 1], p == 0, p + 2 == b.size(), [&](double u, double wu) {
      HalfVectorAngle h = map.angleAt(u);
      double c = h.cosTheta, s = h.sinTheta;
      double kappa = -(cosV / sinV) * (c * c - s * s) / (2.0 * c * s);  // cot(2t) = (c^2 - s^2) / (2 c s)
      if (kappa >= 1.0) return;
      double phiMax = kappa <= -1.0 ? kPi : std::acos(kappa);
      compositeGauss(-phiMax, phiMax, res.phiPanels, [&](double phi, double wphi) { sink.add(h, phi, wu, wphi); });
    });
  return out;
}

}  // namespace mb::energy
