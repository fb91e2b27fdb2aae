// Reference for energy_compensation_none: the identity factor.
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 energyCompensationNone(Vec3, double) { return splat(1.0); }

MB_REFERENCE("energy_compensation_none", energyCompensationNone);

}  // namespace mb::ref
