// Reference for dfg_lut_ue4: Karis 2013, SpecularColor * EnvBRDF.x + EnvBRDF.y.
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 dfgLutUe4(Vec3 f0, double scale, double bias) { return f0 * scale + splat(bias); }

MB_REFERENCE("dfg_lut_ue4", dfgLutUe4);

}  // namespace mb::ref
