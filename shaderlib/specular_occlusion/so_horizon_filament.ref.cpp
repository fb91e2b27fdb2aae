// Reference for so_horizon_filament: h = min(1 + r . n_geometric, 1), squared, r the mirror of
// v about n.
#include <algorithm>

#include "common/reference.hpp"

namespace mb::ref {

static double soHorizonFilament(Geometry g, Vec3 geometricNormal, double, double) {
  Vec3 r = g.n * (2.0 * dot(g.n, g.v)) - g.v;
  double horizon = std::min(1.0 + dot(r, normalize(geometricNormal)), 1.0);
  return horizon * horizon;
}

MB_REFERENCE("so_horizon_filament", soHorizonFilament);

}  // namespace mb::ref
