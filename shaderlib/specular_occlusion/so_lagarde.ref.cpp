// Reference for so_lagarde: Lagarde & de Rousiers 2014 listing 26,
// saturate(pow(NdotV + AO, exp2(-16 roughness - 1)) - 1 + AO) with roughness = alpha.
#include "common/reference.hpp"

namespace mb::ref {

static double soLagarde(Geometry g, Vec3, double ao, double perceptualRoughness) {
  double roughness = perceptualRoughness * perceptualRoughness;
  return clamp01(std::pow(g.NoV + ao, std::exp2(-16.0 * roughness - 1.0)) - 1.0 + ao);
}

MB_REFERENCE("so_lagarde", soLagarde);

}  // namespace mb::ref
