// Reference for v_smith_ggx_correlated_fast: Hammon 2017, G2 / (4 n.l n.v) approximated by
//   V = 1 / (2 ((1 - alpha) 2 n.l n.v + alpha (n.l + n.v))).
// Ground truth: the exact height-correlated Smith-GGX visibility (Heitz 2014 eq. 99).
#include "common/microfacet_reference.hpp"

namespace mb::ref {

static double vSmithGgxCorrelatedFast(Geometry g, double alpha) {
  double blended = (1.0 - alpha) * (2.0 * g.NoL * g.NoV) + alpha * (g.NoL + g.NoV);
  return 1.0 / (2.0 * blended);
}

static double exactCorrelated(Geometry g, double alpha) { return smithGgxCorrelatedV(g.NoV, g.NoL, alpha); }

MB_REFERENCE("v_smith_ggx_correlated_fast", vSmithGgxCorrelatedFast);
MB_GROUND_TRUTH("v_smith_ggx_correlated_fast", exactCorrelated);

}  // namespace mb::ref
