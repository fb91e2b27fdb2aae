// Reference for wrap_none: the cosine factor max(cos theta_l, 0) of the reflectance equation.
#include <algorithm>

#include "common/reference.hpp"

namespace mb::ref {

static Vec3 wrapNone(Geometry g, double, Vec3) { return splat(std::max(0.0, dot(g.n, g.l))); }

MB_REFERENCE("wrap_none", wrapNone);

}  // namespace mb::ref
