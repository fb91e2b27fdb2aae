// Where the energy checks sample: a grid of (n.v, perceptual roughness) for the albedo
// tables, the quadrature resolution, and the random pairs of the reciprocity check. The
// command uses the fine grid; tests use the coarse one (seconds, not minutes).
#pragma once
#include <cstdint>
#include <vector>

#include "energy/albedo_quadrature.hpp"
#include "energy/brick_sweep.hpp"
#include "energy/lobes.hpp"

namespace mb::energy {

struct EnergyGrid {
  std::vector<double> NoV;
  std::vector<double> perceptualRoughness;
  QuadratureResolution resolution;
  uint32_t reciprocityPairs = 0;
  uint64_t seed = 1;
  static EnergyGrid fine();
  static EnergyGrid coarse();
};

struct GridCell {
  double NoV = 0;  // of the fp32 view vector, in double
  double perceptualRoughness = 0;
  ProbeInputs inputs;  // everything but l, which the quadrature node sets
};

// NoV-major: cell (i, j) is at i * perceptualRoughness.size() + j.
std::vector<GridCell> gridCells(const EnergyGrid& grid);

// Roughness inputs of every lobe at perceptual roughness r, rounded to fp32: alpha = r^2
// (Burley 2012); anisotropic lobes take at = 1.5 alpha, ab = 0.5 alpha (Filament's
// alpha (1 +- anisotropy) at anisotropy 0.5, clamped to the bricks' domain) with the tangent
// 30 degrees from the view azimuth, so that neither axis lines up with v.
void setRoughness(ProbeInputs& in, double perceptualRoughness);

// The roughness the lobe's quadrature map uses: the narrower axis for anisotropic lobes.
double mapAlpha(const Lobe& lobe, const ProbeInputs& in);

}  // namespace mb::energy
