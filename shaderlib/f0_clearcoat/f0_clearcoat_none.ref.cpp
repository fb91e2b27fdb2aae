// Reference for f0_clearcoat_none: KHR_materials_clearcoat leaves the base F0 as is.
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 f0ClearcoatNone(Vec3 f0) { return f0; }

MB_REFERENCE("f0_clearcoat_none", f0ClearcoatNone);

}  // namespace mb::ref
