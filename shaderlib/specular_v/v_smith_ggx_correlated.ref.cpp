// Reference for v_smith_ggx_correlated: Heitz 2014 eq. 99 written with the GGX Lambda of
// eq. 72, V = 1 / (4 n.l n.v (1 + Lambda(v) + Lambda(l))), with the n.l = 0 limit
// V = 1 / (2 alpha n.v) taken explicitly (common/microfacet_reference.hpp). The brick is exact
// (not an approximation), so this is also its ground truth.
#include "common/microfacet_reference.hpp"

namespace mb::ref {

static double vSmithGgxCorrelated(Geometry g, double alpha) { return smithGgxCorrelatedV(g.NoV, g.NoL, alpha); }

MB_REFERENCE("v_smith_ggx_correlated", vSmithGgxCorrelated);
MB_GROUND_TRUTH("v_smith_ggx_correlated", vSmithGgxCorrelated);

}  // namespace mb::ref
