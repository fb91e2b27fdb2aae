// Reference for v_implicit: G_implicit(l, v) = (n.l)(n.v), so V = 1/4. Ground truth: exact
// height-correlated Smith-GGX.
#include "common/microfacet_reference.hpp"

namespace mb::ref {

static double vImplicit(Geometry, double) { return 0.25; }

static double exactCorrelated(Geometry g, double alpha) { return smithGgxCorrelatedV(g.NoV, g.NoL, alpha); }

MB_REFERENCE("v_implicit", vImplicit);
MB_GROUND_TRUTH("v_implicit", exactCorrelated);

}  // namespace mb::ref
