// Ground truths and the decisions taken from them, checked on the CPU in double.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "common/reference.hpp"
#include "common/sheen_reference.hpp"
#include "support/pipeline_support.hpp"

using namespace mb;

namespace {

// The variant found in some public implementations: a / ((1 + b x^c) + d x + e).
double charlieVariantLambda(double cosTheta, double r) {
  auto L = [r](double x) {
    double t = 1.0 - (1.0 - r) * (1.0 - r);
    auto blend = [t](double atZero, double atOne) { return (1.0 - t) * atZero + t * atOne; };
    double a = blend(25.3245, 21.5473), b = blend(3.32435, 3.82987), c = blend(0.16801, 0.19823);
    double d = blend(-1.27393, -1.97760), e = blend(-4.85967, -4.32054);
    return a / ((1.0 + b * std::pow(x, c)) + d * x + e);
  };
  if (cosTheta < 0.5) return std::exp(L(cosTheta));
  return std::exp(2.0 * L(0.5) - L(1.0 - cosTheta));
}

double logRatio(double fit, double exact) { return std::abs(std::log(fit / exact)); }

}  // namespace

TEST_CASE("the CharlieL fit form a/(1+b x^c) + d x + e is the paper's, decided by the exact Lambda",
          "[ground-truth][sheen]") {
  // Over r in [0.1, 1] and cos in [0.05, 0.95], compare both published forms with the exact
  // Lambda integral (Heitz 2014 eq. 24). docs/accuracy.md quotes these numbers.
  double worstPaper = 0, worstVariant = 0;
  for (double r = 0.1; r <= 1.0 + 1e-9; r += 0.1)
    for (double c = 0.05; c <= 0.95 + 1e-9; c += 0.05) {
      double exact = ref::charlieExactLambda(c, r);
      worstPaper = std::max(worstPaper, logRatio(ref::charlieFitLambda(c, r), exact));
      worstVariant = std::max(worstVariant, logRatio(charlieVariantLambda(c, r), exact));
    }
  std::ostringstream s;
  s << "worst |ln(fit/exact)|: paper form " << worstPaper << ", variant " << worstVariant;
  INFO(s.str());
  CHECK(worstPaper < std::log(1.25));   // within 25% everywhere
  CHECK(worstVariant > std::log(1e4));  // off by at least four orders of magnitude somewhere
  // The spot value quoted in common/sheen.glsl: r = 0.5, cos = 0.5.
  CHECK(ref::charlieExactLambda(0.5, 0.5) == Approx(0.875).epsilon(0.01));
  CHECK(ref::charlieFitLambda(0.5, 0.5) == Approx(0.944).epsilon(0.01));
}

TEST_CASE("ground truths are registered only for shipped bricks, and agree with exact bricks",
          "[ground-truth][library]") {
  const auto& lib = test::shippedLibrary();
  for (const auto& [id, truth] : ref::Registry::groundTruths().all()) {
    INFO(id);
    const Brick* b = lib.findBrick(id);
    REQUIRE(b != nullptr);
    const ref::Reference* r = ref::Registry::references().find(id);
    REQUIRE(r != nullptr);
    CHECK(truth.params == r->params);
    CHECK(truth.returns == r->returns);
  }
  // Bricks that are exact (not approximations) must equal their own ground truth.
  for (const char* id : {"v_smith_ggx_correlated", "f_dielectric_exact", "f0_clearcoat_exact"}) {
    INFO(id);
    const ref::Reference* r = ref::Registry::references().find(id);
    const ref::Reference* t = ref::Registry::groundTruths().find(id);
    REQUIRE(r != nullptr);
    REQUIRE(t != nullptr);
    size_t inCount = 0;
    for (ValueType p : r->params) inCount += p == ValueType::Geometry ? 9 : componentCount(p);
    std::vector<double> in(inCount);
    for (int trial = 0; trial < 200; ++trial) {
      for (size_t k = 0; k < in.size(); ++k)
        in[k] = 0.05 + 0.9 * std::fmod(0.6180339887 * (trial * 31 + k * 7 + 1), 1.0);
      double a[3] = {0, 0, 0}, bOut[3] = {0, 0, 0};
      r->eval(in.data(), a);
      t->eval(in.data(), bOut);
      for (int k = 0; k < 3; ++k) CHECK(a[k] == Approx(bOut[k]).epsilon(1e-9).margin(1e-12));
    }
  }
}
