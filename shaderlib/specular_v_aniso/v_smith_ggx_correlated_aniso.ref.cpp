// Reference for v_smith_ggx_correlated_aniso: Heitz 2014 eq. 99 with the anisotropic GGX
// Lambda of eq. 86, in pbrt-v4's tan^2 / cos^2(phi) form (v_aniso_reference.hpp), n.l = 0
// taken as its limit. The brick is exact, so this is also its ground truth.
#include "specular_v_aniso/v_aniso_reference.hpp"

namespace mb::ref {

static double vSmithGgxCorrelatedAniso(Geometry g, Vec3 tangent, double at, double ab) {
  return aniso_v::correlated(aniso_v::viewLight(g, tangent), at, ab);
}

MB_REFERENCE("v_smith_ggx_correlated_aniso", vSmithGgxCorrelatedAniso);
MB_GROUND_TRUTH("v_smith_ggx_correlated_aniso", vSmithGgxCorrelatedAniso);

}  // namespace mb::ref
