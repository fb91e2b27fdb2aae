// Reference for v_schlick_ggx_ibl: Schlick's G1 with Karis' image-based-lighting k = alpha/2,
// V = G1(l) G1(v) / (4 n.l n.v), with the n.l = 0 limit G1(l)/n.l -> 1/k. Ground truth: the
// exact height-correlated Smith-GGX visibility.
#include "common/microfacet_reference.hpp"

namespace mb::ref {

static double g1Schlick(double NoX, double k) { return NoX / (NoX * (1.0 - k) + k); }

static double vSchlickGgxIbl(Geometry g, double alpha) {
  double k = alpha / 2.0;
  double g1v = g1Schlick(g.NoV, k);
  if (g.NoL == 0.0) return g1v / (4.0 * g.NoV * k);
  return g1Schlick(g.NoL, k) * g1v / (4.0 * g.NoL * g.NoV);
}

static double exactCorrelated(Geometry g, double alpha) { return smithGgxCorrelatedV(g.NoV, g.NoL, alpha); }

MB_REFERENCE("v_schlick_ggx_ibl", vSchlickGgxIbl);
MB_GROUND_TRUTH("v_schlick_ggx_ibl", exactCorrelated);

}  // namespace mb::ref
