// Reference for v_cook_torrance: Cook & Torrance 1982,
//   G = min(1, 2 (n.h)(n.v)/(v.h), 2 (n.h)(n.l)/(v.h)),  V = G / (4 (n.l)(n.v)),
// with the n.l = 0 limit V = (n.h) / (2 (v.h)(n.v)) (the n.l term is the minimum there).
// Ground truth: exact height-correlated Smith-GGX.
#include <algorithm>

#include "common/microfacet_reference.hpp"

namespace mb::ref {

static double vCookTorrance(Geometry g, double) {
  if (g.NoL == 0.0) return g.NoH / (2.0 * g.VoH * g.NoV);
  double G = std::min({1.0, 2.0 * g.NoH * g.NoV / g.VoH, 2.0 * g.NoH * g.NoL / g.VoH});
  return G / (4.0 * g.NoL * g.NoV);
}

static double exactCorrelated(Geometry g, double alpha) { return smithGgxCorrelatedV(g.NoV, g.NoL, alpha); }

MB_REFERENCE("v_cook_torrance", vCookTorrance);
MB_GROUND_TRUTH("v_cook_torrance", exactCorrelated);

}  // namespace mb::ref
