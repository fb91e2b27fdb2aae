// Reference for v_ashikhmin: Neubelt & Pettineo 2013, V = 1 / (4 (n.l + n.v - n.l n.v)).
#include "common/reference.hpp"

namespace mb::ref {

static double vAshikhmin(Geometry g, double) { return 1.0 / (4.0 * (g.NoL + g.NoV - g.NoL * g.NoV)); }

MB_REFERENCE("v_ashikhmin", vAshikhmin);

}  // namespace mb::ref
