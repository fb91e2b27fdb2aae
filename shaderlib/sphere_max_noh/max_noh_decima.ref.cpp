// Reference for max_noh_decima: de Carpentier 2017 / UE4 SphereMaxNoH without the Newton step
// (seed 002), from its scalar equations: RoL = 2 NoL NoV - VoL; RoL >= cos a -> n.h = 1; else
//   rInvLengthT = sin a / sqrt(1 - RoL^2), NoTr = rInvLengthT (NoV - RoL NoL),
//   VoTr = rInvLengthT (2 NoV^2 - 1 - RoL VoL), NoL' = NoL cos a + NoTr, VoL' = VoL cos a + VoTr,
//   n.h = saturate((NoL' + NoV) / sqrt(2 + 2 VoL'))   (lights_reference.hpp, decimaRim).
// Ground truth: the exact max of n.h over the cap.
#include "common/lights_reference.hpp"

namespace mb::ref {

static double maxNoHDecima(Geometry g, double sinAlpha) {
  lights::DecimaRim d = lights::decimaRim(g, sinAlpha);
  if (d.inside) return 1.0;
  return lights::decimaNoH(d, d.NoTr, d.VoTr);
}

MB_REFERENCE("max_noh_decima", maxNoHDecima);
MB_GROUND_TRUTH("max_noh_decima", lights::maxNoHOverCap);

}  // namespace mb::ref
