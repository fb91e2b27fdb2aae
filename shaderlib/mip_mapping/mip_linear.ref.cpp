// Reference for mip_linear: the prefiltered mip chain indexed linearly by perceptual roughness.
// Ground truth: the cone-footprint level (Unity's accurate mapping) at the same n.r, which the
// fitted curves stand in for.
#include "common/ibl_reference.hpp"

namespace mb::ref {

static double mipLinear(double perceptualRoughness, double, double maxMip) { return perceptualRoughness * maxMip; }

static double footprint(double perceptualRoughness, double NoR, double maxMip) {
  return coneFootprintMip(perceptualRoughness, NoR, maxMip);
}

MB_REFERENCE("mip_linear", mipLinear);
MB_GROUND_TRUTH("mip_linear", footprint);

}  // namespace mb::ref
