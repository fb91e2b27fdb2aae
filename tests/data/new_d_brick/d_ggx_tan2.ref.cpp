// Reference for the test brick d_ggx_tan2 (tests/data/new_d_brick/): Walter et al. 2007,
// eq. 33, as D(h) = alpha^2 / (pi (cos^2 alpha^2 + sin^2)^2), in double precision. A new
// brick's reference lives beside its GLSL in shaderlib/ and is compiled into every program
// (CMake globs shaderlib/*.cpp); this one is compiled into mb_tests only, so the shipped
// library and its programs do not change.
#include "common/reference.hpp"

namespace mb::ref {

static double dGgxTan2(const Geometry& g, double alpha) {
  double cos2 = g.NoH * g.NoH;
  double a2 = alpha * alpha;
  double e = cos2 * a2 + (1.0 - cos2);
  return a2 / (kPi * e * e);
}

MB_REFERENCE("d_ggx_tan2", dGgxTan2);

}  // namespace mb::ref
