// Reference for diffuse_lambert: a perfectly diffuse reflector with unit albedo has
// f = 1/pi, since the cosine-weighted hemisphere integral of a constant c is pi * c.
#include "common/reference.hpp"

namespace mb::ref {

static double diffuseLambert(Geometry, double, double) { return 1.0 / kPi; }

MB_REFERENCE("diffuse_lambert", diffuseLambert);

}  // namespace mb::ref
