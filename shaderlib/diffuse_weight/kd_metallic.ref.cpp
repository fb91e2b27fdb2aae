// Reference for kd_metallic: metals have no diffuse, dielectrics a full one; linear in between.
#include "common/reference.hpp"

namespace mb::ref {

static Vec3 kdMetallic(Vec3, double metallic) { return splat(1.0 - metallic); }

MB_REFERENCE("kd_metallic", kdMetallic);

}  // namespace mb::ref
