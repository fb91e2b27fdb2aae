// Reference for coat_base_roughness_max: seed 000, r' = r + (max(r, r_c) - r) c.
#include <algorithm>

#include "common/reference.hpp"

namespace mb::ref {

static double coatBaseRoughnessMax(double r, double rc, double c) { return r + (std::max(r, rc) - r) * c; }

MB_REFERENCE("coat_base_roughness_max", coatBaseRoughnessMax);

}  // namespace mb::ref
