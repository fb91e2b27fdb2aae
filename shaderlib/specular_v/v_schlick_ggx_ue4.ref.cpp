// Reference for v_schlick_ggx_ue4: Karis 2013, Schlick's G1 with k = (roughness + 1)^2 / 8,
// G = G1(l) G1(v), V = G / (4 n.l n.v). At n.l = 0, G1(l) / n.l -> 1 / k (limit taken
// explicitly). Ground truth: the exact height-correlated Smith-GGX visibility it stands in
// for (Heitz 2014 eq. 99).
#include "common/microfacet_reference.hpp"

namespace mb::ref {

static double schlickG1(double NoX, double k) { return NoX / (NoX * (1.0 - k) + k); }

static double vSchlickGgxUe4(Geometry g, double alpha) {
  double roughness = std::sqrt(alpha);  // UE4 roughness: alpha = roughness^2
  double k = (roughness + 1.0) * (roughness + 1.0) / 8.0;
  double g1v = schlickG1(g.NoV, k);
  if (g.NoL == 0.0) return g1v / (4.0 * g.NoV * k);  // lim G1(l)/n.l = 1/k
  double G = schlickG1(g.NoL, k) * g1v;
  return G / (4.0 * g.NoL * g.NoV);
}

static double vSchlickGgxUe4Truth(Geometry g, double alpha) { return smithGgxCorrelatedV(g.NoV, g.NoL, alpha); }

MB_REFERENCE("v_schlick_ggx_ue4", vSchlickGgxUe4);
MB_GROUND_TRUTH("v_schlick_ggx_ue4", vSchlickGgxUe4Truth);

}  // namespace mb::ref
