// Reference for dfg_lut_filament: with Schlick's F = f0 + (1 - f0) Fc inside the integral,
// Int Gv F = f0 Int Gv + (1 - f0) Int Gv Fc.
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 dfgLutFilament(Vec3 f0, double intGvFc, double intGv) { return f0 * intGv + (splat(1.0) - f0) * intGvFc; }

MB_REFERENCE("dfg_lut_filament", dfgLutFilament);

}  // namespace mb::ref
