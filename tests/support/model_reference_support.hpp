// Helpers of the shading models' reference cross-checks (tests/test_model_*.cpp).
// hemisphereIntegral: brute-force integral over the hemisphere around a unit normal. A model
// lit by a constant environment of radiance 1 reflects Int_H f(l, v) (n.l) dw_l, i.e. the
// integral of its response to a directional light of unit illuminance from every direction
// l. Written in light-direction space (not over half vectors as ibl_reference.hpp and
// cloth_dfg_reference.hpp are), so that the two quadratures are independent:
// l = sin(t) (cos(p) t1 + sin(p) t2) + cos(t) n, dw = d(cos t) dp, composite 8-point
// Gauss-Legendre in cos t and in p.
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "common/ibl_reference.hpp"
#include "common/model_reference.hpp"

namespace mb::test {

// The registered reference composition of `model`.
inline ref::ModelReferenceFn modelReference(const std::string& model) {
  ref::ModelReferenceFn fn = ref::ModelRegistry::instance().find(model);
  if (!fn) throw std::logic_error("no '" + model + "' model reference registered");
  return fn;
}

// A unit view direction at n.v = NoV from n = z.
inline ref::Vec3 viewAt(double NoV) { return {std::sqrt(1.0 - NoV * NoV), 0.0, NoV}; }

inline double maxComponentDiff(const ref::Vec3& a, const ref::Vec3& b) {
  return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}

inline ref::Vec3 hemisphereIntegral(const ref::Vec3& n, const std::function<ref::Vec3(const ref::Vec3&)>& f,
                                    int cosPanels = 24, int phiPanels = 48) {
  static const ref::detail_ibl::GaussLegendre<8> gl;
  ref::Vec3 helper = std::abs(n.x) < 0.9 ? ref::Vec3{1, 0, 0} : ref::Vec3{0, 1, 0};
  const ref::Vec3 t1 = ref::normalize(ref::cross(helper, n)), t2 = ref::cross(n, t1);
  ref::Vec3 sum;
  const double du = 1.0 / cosPanels, dp = 2.0 * ref::kPi / phiPanels;
  for (int a = 0; a < cosPanels; ++a)
    for (int i = 0; i < 8; ++i) {
      const double u = du * (a + 0.5 + 0.5 * gl.x[i]), s = std::sqrt(std::max(0.0, 1.0 - u * u));
      for (int b = 0; b < phiPanels; ++b)
        for (int j = 0; j < 8; ++j) {
          const double p = dp * (b + 0.5 + 0.5 * gl.x[j]);
          const ref::Vec3 l = t1 * (s * std::cos(p)) + t2 * (s * std::sin(p)) + n * u;
          sum = sum + f(l) * (0.25 * du * dp * gl.w[i] * gl.w[j]);
        }
    }
  return sum;
}

}  // namespace mb::test
