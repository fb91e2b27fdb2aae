// Reference for so_horizon_marmoset: the mirror direction r = 2 (n.v) n - v, horizon factor
// saturate(1 + 1.3 (r . n_geometric)), squared (Russell 2014).
#include "common/reference.hpp"

namespace mb::ref {

static double soHorizonMarmoset(Geometry g, Vec3 geometricNormal, double, double) {
  Vec3 r = g.n * (2.0 * dot(g.n, g.v)) - g.v;
  double horizon = clamp01(1.0 + 1.3 * dot(r, normalize(geometricNormal)));
  return horizon * horizon;
}

MB_REFERENCE("so_horizon_marmoset", soHorizonMarmoset);

}  // namespace mb::ref
