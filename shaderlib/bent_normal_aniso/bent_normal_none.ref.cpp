// Reference for bent_normal_none: the unit shading normal n.
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 bentNormalNone(Geometry g, Vec3, double, double) { return g.n; }

MB_REFERENCE("bent_normal_none", bentNormalNone);

}  // namespace mb::ref
