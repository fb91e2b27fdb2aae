// Reference for mip_unity_accurate: the cone-footprint mapping written as published (Phong
// exponent n = 2/m^2 - 2, divided by 4 n.r, back to r' = (2/(n+2))^(1/4)), with the m = 0
// mirror limit explicit (common/ibl_reference.hpp). Exact by definition: also its ground truth.
#include "common/ibl_reference.hpp"

namespace mb::ref {

static double mipUnityAccurate(double perceptualRoughness, double NoR, double maxMip) {
  return coneFootprintMip(perceptualRoughness, NoR, maxMip);
}

MB_REFERENCE("mip_unity_accurate", mipUnityAccurate);
MB_GROUND_TRUTH("mip_unity_accurate", mipUnityAccurate);

}  // namespace mb::ref
