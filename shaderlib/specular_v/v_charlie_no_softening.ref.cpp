// Reference for v_charlie_no_softening: Estevez & Kulla 2017, G = 1 / (1 + Lambda(v) +
// Lambda(l)) with the fitted Lambda, V = G / (4 n.l n.v). Ground truth: the exact Charlie
// Lambda from its defining integral (common/sheen_reference.hpp).
#include "common/sheen_reference.hpp"

namespace mb::ref {

static double vCharlieNoSoftening(Geometry g, double r) {
  double G = 1.0 / (1.0 + charlieFitLambda(g.NoV, r) + charlieFitLambda(g.NoL, r));
  return G / (4.0 * g.NoL * g.NoV);
}

// (1 + Lambda(v) + Lambda(l)) 4 n.v n.l = 4 n.v (n.l (1 + Lambda(v)) + A(l)) with
// A(l) = Lambda(l) n.l the back-facing projected area: finite at n.l = 0, where the exact V
// tends to 1 / (4 n.v A(l)).
static double vCharlieNoSofteningTruth(Geometry g, double r) {
  double lambdaV = charlieExactLambda(g.NoV, r);
  double areaL = charlieBackfacingArea(g.NoL, r);
  return 1.0 / (4.0 * g.NoV * (g.NoL * (1.0 + lambdaV) + areaL));
}

MB_REFERENCE("v_charlie_no_softening", vCharlieNoSoftening);
MB_GROUND_TRUTH("v_charlie_no_softening", vCharlieNoSofteningTruth);

}  // namespace mb::ref
