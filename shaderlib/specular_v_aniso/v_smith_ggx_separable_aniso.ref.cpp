// Reference for v_smith_ggx_separable_aniso: Heitz 2014 eq. 98, G2 = G1(v) G1(l) with the
// anisotropic GGX Lambda of eq. 86 (pbrt-v4 form, v_aniso_reference.hpp), n.l = 0 taken as
// its limit. Ground truth: the height-correlated form (eq. 99) that the separable one
// approximates.
#include "specular_v_aniso/v_aniso_reference.hpp"

namespace mb::ref {

static double vSmithGgxSeparableAniso(Geometry g, Vec3 tangent, double at, double ab) {
  return aniso_v::separable(aniso_v::viewLight(g, tangent), at, ab);
}

static double exactCorrelatedAniso(Geometry g, Vec3 tangent, double at, double ab) {
  return aniso_v::correlated(aniso_v::viewLight(g, tangent), at, ab);
}

MB_REFERENCE("v_smith_ggx_separable_aniso", vSmithGgxSeparableAniso);
MB_GROUND_TRUTH("v_smith_ggx_separable_aniso", exactCorrelatedAniso);

}  // namespace mb::ref
