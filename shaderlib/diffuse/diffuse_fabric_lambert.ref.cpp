// Reference for diffuse_fabric_lambert: Unity's FabricLambert, (1 - alpha/2) / pi, i.e. a
// Lambertian lobe whose albedo falls linearly from 1 to 0.5 with alpha (seed 000 passes its
// "roughness", which it defines as alpha = perceptual roughness squared).
#include "common/reference.hpp"

namespace mb::ref {

static double diffuseFabricLambert(Geometry, double, double alpha) { return (1.0 - 0.5 * alpha) / kPi; }

MB_REFERENCE("diffuse_fabric_lambert", diffuseFabricLambert);

}  // namespace mb::ref
