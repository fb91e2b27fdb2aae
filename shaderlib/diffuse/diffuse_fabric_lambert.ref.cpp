// Reference for diffuse_fabric_lambert: Unity HDRP's FabricLambert, (1 - r/2) / pi, i.e. a
// Lambertian lobe whose albedo falls linearly from 1 to 0.5 with perceptual roughness r.
#include "common/reference.hpp"

namespace mb::ref {

static double diffuseFabricLambert(Geometry, double perceptualRoughness, double) {
  return (1.0 - 0.5 * perceptualRoughness) / kPi;
}

MB_REFERENCE("diffuse_fabric_lambert", diffuseFabricLambert);

}  // namespace mb::ref
