// Reference for v_smith_ggx_separable: Heitz 2014 eq. 98, G2 = G1(v) G1(l) with
// G1 = 1 / (1 + Lambda) and the GGX Lambda of eq. 72; V = G2 / (4 n.l n.v), with the n.l = 0
// limit G1(l)/n.l -> 2/alpha. Ground truth: the height-correlated form (eq. 99), the more
// accurate Smith model that the separable one approximates.
#include "common/microfacet_reference.hpp"

namespace mb::ref {

static double g1(double cosTheta, double alpha) { return 1.0 / (1.0 + smithGgxLambda(cosTheta, alpha)); }

static double vSmithGgxSeparable(Geometry g, double alpha) {
  double g1v = g1(g.NoV, alpha);
  if (g.NoL == 0.0) return g1v * (2.0 / alpha) / (4.0 * g.NoV);
  return g1v * g1(g.NoL, alpha) / (4.0 * g.NoL * g.NoV);
}

static double exactCorrelated(Geometry g, double alpha) { return smithGgxCorrelatedV(g.NoV, g.NoL, alpha); }

MB_REFERENCE("v_smith_ggx_separable", vSmithGgxSeparable);
MB_GROUND_TRUTH("v_smith_ggx_separable", exactCorrelated);

}  // namespace mb::ref
