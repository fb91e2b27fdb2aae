// Reference for v_charlie: Estevez & Kulla 2017, height-correlated masking-shadowing
// G = 1 / (1 + Lambda(v) + Lambda(l)) with the fitted Lambda and the terminator softening
// Lambda^(1 + 2 (1 - cos)^8) on both directions (as seed 000 does), V = G / (4 n.l n.v).
// Ground truth: the same with the exact Charlie Lambda integral (softened the same way, so
// the bench measures the fit alone).
#include "common/sheen_reference.hpp"

namespace mb::ref {

static double vCharlie(Geometry g, double r) {
  double lambdaV = charlieSoften(charlieFitLambda(g.NoV, r), g.NoV);
  double lambdaL = charlieSoften(charlieFitLambda(g.NoL, r), g.NoL);
  double G = 1.0 / (1.0 + lambdaV + lambdaL);
  return G / (4.0 * g.NoL * g.NoV);
}

static double vCharlieTruth(Geometry g, double r) {
  // Softened Lambda(l) ~ (A/n.l)^3 at n.l -> 0, so V -> 0 there.
  if (g.NoL == 0.0) return 0.0;
  double lambdaV = charlieSoften(charlieExactLambda(g.NoV, r), g.NoV);
  double lambdaL = charlieSoften(charlieExactLambda(g.NoL, r), g.NoL);
  return 1.0 / ((1.0 + lambdaV + lambdaL) * 4.0 * g.NoL * g.NoV);
}

MB_REFERENCE("v_charlie", vCharlie);
MB_GROUND_TRUTH("v_charlie", vCharlieTruth);

}  // namespace mb::ref
