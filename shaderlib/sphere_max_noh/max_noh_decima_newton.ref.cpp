// Reference for max_noh_decima_newton: de Carpentier 2017 / UE4 SphereMaxNoH with
// bNewtonIteration (seed 002), its scalar equations in double: the rim point of
// max_noh_decima, rotated on the rim by theta with tan(theta/2) = xNum / xDenom,
//   NxLoV = sqrt(1 - NoL^2 - NoV^2 - VoL^2 + 2 NoL NoV VoL), NoBr = rInvLengthT NxLoV,
//   VoBr = 2 NoV NoBr, NoLVTr = NoL cos a + NoV + NoTr, VoLVTr = VoL cos a + 1 + VoTr,
//   p = NoBr VoLVTr, q = NoLVTr VoLVTr, s = VoBr NoLVTr, xNum = q (-p/2 + VoBr NoLVTr / 4),
//   xDenom = p^2 + s (s - 2p) + NoLVTr ((NoL cos a + NoV) VoLVTr^2 + q (-(VoLVTr + VoL cos a)/2 - 1/2)),
//   sin(theta) = 2 xNum xDenom / (xDenom^2 + xNum^2), cos(theta) = 1 - 2 xNum^2 / (...).
// Ground truth: the exact max of n.h over the cap.
#include "common/lights_reference.hpp"

namespace mb::ref {

static double maxNoHDecimaNewton(Geometry g, double sinAlpha) {
  lights::DecimaRim d = lights::decimaRim(g, sinAlpha);
  if (d.inside) return 1.0;
  if (d.point) return lights::decimaNoH(d, 0.0, 0.0);
  double NoL = d.NoL, NoV = d.NoV, VoL = d.VoL, cosAlpha = d.cosAlpha;
  double NxLoV = std::sqrt(clamp01(1.0 - NoL * NoL - NoV * NoV - VoL * VoL + 2.0 * NoL * NoV * VoL));
  double NoBr = d.rInvLengthT * NxLoV, VoBr = d.rInvLengthT * NxLoV * 2.0 * NoV;
  double NoLVTr = NoL * cosAlpha + NoV + d.NoTr, VoLVTr = VoL * cosAlpha + 1.0 + d.VoTr;
  double p = NoBr * VoLVTr, q = NoLVTr * VoLVTr, s = VoBr * NoLVTr;
  double xNum = q * (-0.5 * p + 0.25 * VoBr * NoLVTr);
  double xDenom = p * p + s * (s - 2.0 * p) +
                  NoLVTr * ((NoL * cosAlpha + NoV) * VoLVTr * VoLVTr + q * (-0.5 * (VoLVTr + VoL * cosAlpha) - 0.5));
  double twoX1 = 2.0 * xNum / (xDenom * xDenom + xNum * xNum);
  double sinTheta = twoX1 * xDenom, cosTheta = 1.0 - twoX1 * xNum;
  return lights::decimaNoH(d, cosTheta * d.NoTr + sinTheta * NoBr, cosTheta * d.VoTr + sinTheta * VoBr);
}

MB_REFERENCE("max_noh_decima_newton", maxNoHDecimaNewton);
MB_GROUND_TRUTH("max_noh_decima_newton", lights::maxNoHOverCap);

}  // namespace mb::ref
