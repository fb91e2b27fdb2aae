// Importance maps for the white-furnace quadrature: the inverse CDF of a half-vector
// distribution pdf(h) = D(h) (n.h) over the hemisphere (the standard microfacet sampling
// density; Walter et al. 2007 sec. 5.3). Integrating over u = CDF(theta_h) instead of theta_h
// puts the quadrature nodes where the lobe is, so a lobe of alpha = 0.002 converges as fast
// as a rough one: with the lobe's own D as the map, D / pdf is 1 / (n.h) and the integrand
// in u is smooth whatever the roughness.
#pragma once

namespace mb::energy {

enum class HalfVectorMapKind {
  Cosine,     // pdf = (n.h) / pi: diffuse lobes (no peak)
  Ggx,        // GGX D (Walter et al. 2007 eq. 33)
  Beckmann,   // Beckmann D (Walter et al. 2007 eq. 25)
  Charlie,    // Charlie sheen D (Estevez & Kulla 2017 eq. 2)
  Ashikhmin,  // Ashikhmin velvet D, normalized (Neubelt & Pettineo 2013)
};

const char* mapName(HalfVectorMapKind kind);

struct HalfVectorAngle {
  double cosTheta = 1;
  double sinTheta = 0;
};

class HalfVectorMap {
 public:
  HalfVectorMap(HalfVectorMapKind kind, double alpha);
  // P(theta_h <= theta): the fraction of the distribution within theta of n.
  double cdf(double theta) const;
  // The inverse of cdf: theta_h at u in [0, 1].
  HalfVectorAngle angleAt(double u) const;
  // pdf per steradian of h: D(h) (n.h). u = cdf(theta) gives d(omega_h) = du dphi / (2 pi pdf).
  double density(const HalfVectorAngle& a) const;

 private:
  HalfVectorMapKind kind_;
  double alpha_;
};

}  // namespace mb::energy
