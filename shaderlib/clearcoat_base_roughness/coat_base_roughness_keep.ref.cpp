// Reference for coat_base_roughness_keep: KHR_materials_clearcoat leaves the base roughness as is.
#include "common/reference.hpp"

namespace mb::ref {

static double coatBaseRoughnessKeep(double r, double, double) { return r; }

MB_REFERENCE("coat_base_roughness_keep", coatBaseRoughnessKeep);

}  // namespace mb::ref
