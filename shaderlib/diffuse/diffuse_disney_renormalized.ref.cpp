// Reference for diffuse_disney_renormalized: Lagarde & de Rousiers 2014, listing 1 (the
// Burley 2012 Disney diffuse with Frostbite's energy bias and factor), divided by pi:
//   f_d = energyFactor * F_Schlick(1, fd90, n.l) * F_Schlick(1, fd90, n.v) / pi.
#include "common/reference.hpp"

namespace mb::ref {

static double schlick(double f0, double f90, double u) { return f0 + (f90 - f0) * std::pow(1.0 - u, 5.0); }

static double diffuseDisneyRenormalized(Geometry g, double linearRoughness, double) {
  double energyBias = 0.0 + (0.5 - 0.0) * linearRoughness;
  double energyFactor = 1.0 + (1.0 / 1.51 - 1.0) * linearRoughness;
  double fd90 = energyBias + 2.0 * g.LoH * g.LoH * linearRoughness;
  double lightScatter = schlick(1.0, fd90, g.NoL);
  double viewScatter = schlick(1.0, fd90, g.NoV);
  return lightScatter * viewScatter * energyFactor / kPi;
}

MB_REFERENCE("diffuse_disney_renormalized", diffuseDisneyRenormalized);

}  // namespace mb::ref
