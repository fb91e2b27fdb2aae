// Reference for mip_unity: mip = (1.7 r - 0.7 r^2) maxMip. Ground truth: the cone-footprint
// level at the same n.r (Unity's accurate mapping).
#include "common/ibl_reference.hpp"

namespace mb::ref {

static double mipUnity(double r, double, double maxMip) { return (1.7 * r - 0.7 * r * r) * maxMip; }

static double footprint(double perceptualRoughness, double NoR, double maxMip) {
  return coneFootprintMip(perceptualRoughness, NoR, maxMip);
}

MB_REFERENCE("mip_unity", mipUnity);
MB_GROUND_TRUTH("mip_unity", footprint);

}  // namespace mb::ref
