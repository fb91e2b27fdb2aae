// The integrated ground truths are the yardstick of the DFG LUT (docs/lut.md): ref::dfgIntegrals
// and ref::clothDfgIntegral must be good to 1e-7 everywhere, the LUT's grazing column and
// smoothest rows included. Checked two ways, in double on the CPU: (1) self-convergence of the
// adaptive rules (default tolerance against a 1000x tighter one), and (2) an independent
// computation over light directions (not half vectors) where a plain tensor rule converges.
#include <catch2/catch.hpp>

#include <cmath>

#include "common/cloth_dfg_reference.hpp"
#include "common/ibl_reference.hpp"

using namespace mb;

namespace {

// Texel centres of the extreme LUT rows and columns (16^2 .. 1024^2) and interior points.
const double kNoV[] = {0.5 / 1024, 0.5 / 256, 0.5 / 64, 0.5 / 16, 0.1, 0.5, 0.9, 1.0 - 0.5 / 1024};
const double kRoughness[] = {0.5 / 1024, 0.5 / 256, 0.5 / 16, 0.045, 0.2, 0.5, 0.8, 1.0 - 0.5 / 1024};

// Int over the hemisphere of l of f(l) (n.l) dw_l = Int_0^{pi/2} Int_0^{2 pi} f sin(theta) cos(theta),
// by composite 8-point Gauss-Legendre in theta_l and phi_l (64 panels each, phi on [0, pi]
// by symmetry): an integration variable the references do not use.
template <class F>
double overLightDirections(double NoV, const F& f) {
  static const ref::detail_quad::GaussLegendre<8> gl;
  const double sinV = std::sqrt(1.0 - NoV * NoV);
  const ref::Vec3 v{sinV, 0.0, NoV};
  constexpr int kPanels = 64;
  double sum = 0.0;
  for (int pt = 0; pt < kPanels; ++pt)
    for (int it = 0; it < 8; ++it) {
      const double th = 0.5 * ref::kPi * (pt + 0.5 + 0.5 * gl.x[it]) / kPanels;
      const double wt = 0.5 * ref::kPi / kPanels * 0.5 * gl.w[it];
      for (int pp = 0; pp < kPanels; ++pp)
        for (int ip = 0; ip < 8; ++ip) {
          const double ph = ref::kPi * (pp + 0.5 + 0.5 * gl.x[ip]) / kPanels;
          const double wp = ref::kPi / kPanels * 0.5 * gl.w[ip];
          const ref::Vec3 l{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
          sum += 2.0 * wt * wp * std::sin(th) * l.z * f(v, l);
        }
    }
  return sum;
}

}  // namespace

TEST_CASE("dfgIntegrals and clothDfgIntegral converge to 1e-7 at every extreme of the LUT", "[references][lut]") {
  for (double NoV : kNoV)
    for (double r : kRoughness) {
      const double alpha = r * r;
      const ref::DfgIntegrals a = ref::dfgIntegrals(NoV, alpha), b = ref::dfgIntegrals(NoV, alpha, 1e-13);
      INFO("n.v " << NoV << " roughness " << r << ": Int Gv " << a.gv << " vs " << b.gv << ", Int Gv Fc " << a.gvFc
                  << " vs " << b.gvFc);
      CHECK(std::abs(a.gv - b.gv) < 1e-8);
      CHECK(std::abs(a.gvFc - b.gvFc) < 1e-8);
      CHECK(a.gv > 0.0);
      CHECK(a.gv <= 1.0 + 1e-12);  // single scattering cannot create energy
      const double c = ref::clothDfgIntegral(NoV, alpha), d = ref::clothDfgIntegral(NoV, alpha, 1e-13);
      INFO("cloth " << c << " vs " << d);
      CHECK(std::abs(c - d) <= 1e-8 * std::abs(d) + 1e-300);
    }
}

TEST_CASE("dfgIntegrals and clothDfgIntegral agree with an integral over light directions", "[references][lut]") {
  // Moderate roughness and view angles, where the tensor rule over l converges to ~1e-9.
  for (double NoV : {0.2, 0.5, 0.9})
    for (double r : {0.6, 0.8, 1.0}) {
      const double alpha = r * r;
      auto halfVector = [](const ref::Vec3& v, const ref::Vec3& l) { return ref::normalize(v + l); };
      // GGX: f = D G2 / (4 n.l n.v) = D V; the Fc weight (1 - v.h)^5.
      auto ggx = [&](const ref::Vec3& v, const ref::Vec3& l, bool fresnel) {
        const ref::Vec3 h = halfVector(v, l);
        const double a2 = alpha * alpha, c = h.z, dd = c * c * (a2 - 1.0) + 1.0;
        const double D = a2 / (ref::kPi * dd * dd), VoH = ref::dot(v, h);
        return D * ref::smithGgxCorrelatedV(v.z, l.z, alpha) * (fresnel ? std::pow(1.0 - VoH, 5.0) : 1.0);
      };
      auto cloth = [&](const ref::Vec3& v, const ref::Vec3& l) {
        const ref::Vec3 h = halfVector(v, l);
        const double sin2 = 1.0 - h.z * h.z;
        const double D = (2.0 + 1.0 / alpha) * std::pow(sin2, 0.5 / alpha) / (2.0 * ref::kPi);
        return D / (4.0 * (l.z + v.z - l.z * v.z));
      };
      const ref::DfgIntegrals q = ref::dfgIntegrals(NoV, alpha);
      const double gv = overLightDirections(NoV, [&](auto& v, auto& l) { return ggx(v, l, false); });
      const double gvFc = overLightDirections(NoV, [&](auto& v, auto& l) { return ggx(v, l, true); });
      const double c = overLightDirections(NoV, cloth);
      INFO("n.v " << NoV << " roughness " << r << ": " << q.gv << " / " << gv << ", " << q.gvFc << " / " << gvFc
                  << ", cloth " << ref::clothDfgIntegral(NoV, alpha) << " / " << c);
      CHECK(std::abs(q.gv - gv) < 1e-7);
      CHECK(std::abs(q.gvFc - gvFc) < 1e-7);
      CHECK(std::abs(ref::clothDfgIntegral(NoV, alpha) - c) < 1e-7 * c);
    }
}
