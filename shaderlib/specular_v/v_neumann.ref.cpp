// Reference for v_neumann: Neumann et al. 1999, G = (n.l)(n.v) / max(n.l, n.v);
// V = G / (4 n.l n.v) (n.l = 0: the limit 1 / (4 n.v)). Ground truth: exact correlated Smith-GGX.
#include <algorithm>

#include "common/microfacet_reference.hpp"

namespace mb::ref {

static double vNeumann(Geometry g, double) {
  if (g.NoL == 0.0) return 1.0 / (4.0 * g.NoV);
  double G = g.NoL * g.NoV / std::max(g.NoL, g.NoV);
  return G / (4.0 * g.NoL * g.NoV);
}

static double exactCorrelated(Geometry g, double alpha) { return smithGgxCorrelatedV(g.NoV, g.NoL, alpha); }

MB_REFERENCE("v_neumann", vNeumann);
MB_GROUND_TRUTH("v_neumann", exactCorrelated);

}  // namespace mb::ref
