// Quadrature for the directional albedo of a lobe, A(v) = Int f(v, l) (n.l) d(omega_l) over
// the upper hemisphere, at n = +z and v in the xz-plane.
//
// The integral is taken over half vectors: d(omega_l) = 4 (v.h) d(omega_h) (Walter et al.
// 2007 eq. 14), and h is parameterized by u = CDF(theta_h) of an importance map
// (half_vector_map.hpp) and the azimuth phi. The horizon n.l = 0 is placed exactly: with
// l = 2 (v.h) h - v, n.l > 0 is cos(phi) > -cot(theta_v) cot(2 theta_h), so
//   theta_h <= (pi/2 - theta_v) / 2  keeps every azimuth (periodic in phi: trapezoid rule,
//                                    spectrally accurate), and
//   theta_h >= (pi/2 + theta_v) / 2  keeps none;
// in between, phi runs over [-phiMax, phiMax] (composite Gauss-Legendre). In u, panels of 8
// Gauss-Legendre nodes end at the union of three sets of breakpoints: uniform in u
// (importance), uniform in theta_h (no panel spans a wide angle where the map is steep), and,
// in the partial band, uniform in phiMax (at grazing v, phiMax drops from pi to pi/2 within
// ~1/tan(theta_v) of the band's start). The band's first and last panels substitute
// u = u0 + (u1 - u0) t^2, which removes the square-root behaviour of phiMax at the band ends.
// Every node thus sits inside the hemisphere, on a smooth integrand: no node straddles the
// horizon kink, which is what limits a plain l-grid to first-order convergence.
#pragma once
#include <vector>

#include "common/reference.hpp"
#include "energy/half_vector_map.hpp"

namespace mb::energy {

struct QuadratureResolution {
  int thetaPanels = 8;  // P: per theta_h band, up to 2P (3P) panels of 8 Gauss-Legendre nodes in u
  int phiPanels = 4;    // panels of 8 Gauss-Legendre nodes in phi (8 x this trapezoid nodes
                        // over the full circle)
  QuadratureResolution halved() const { return {(thetaPanels + 1) / 2, (phiPanels + 1) / 2}; }
};

struct AlbedoNode {
  ref::Vec3 l;          // unit light direction, n.l > 0
  double weight = 0.0;  // A(v) ~= Sum weight * f(v, l); includes n.l and the Jacobians
};

// `v`: unit, with v.y = 0 and v.z = n.v > 0.
std::vector<AlbedoNode> albedoNodes(const ref::Vec3& v, const HalfVectorMap& map, const QuadratureResolution& res);

}  // namespace mb::energy
