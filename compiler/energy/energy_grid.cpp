#include "energy/energy_grid.hpp"

#include <algorithm>
#include <cmath>

namespace mb::energy {
namespace {

double fp32(double x) { return static_cast<float>(x); }

}  // namespace

EnergyGrid EnergyGrid::fine() {
  EnergyGrid g;
  g.NoV = {0.02, 0.05, 0.1, 0.2, 0.35, 0.5, 0.7, 0.85, 1.0};
  // 0.045: the fp32 minimum perceptual roughness (seed 000), alpha = 0.002025.
  g.perceptualRoughness = {0.045, 0.1, 0.2, 0.3, 0.5, 0.7, 0.85, 1.0};
  g.resolution = {16, 8};
  g.reciprocityPairs = 4096;
  return g;
}

EnergyGrid EnergyGrid::coarse() {
  EnergyGrid g;
  g.NoV = {0.05, 0.5, 1.0};
  g.perceptualRoughness = {0.045, 0.5, 1.0};
  g.resolution = {8, 4};
  g.reciprocityPairs = 512;
  return g;
}

void setRoughness(ProbeInputs& in, double r) {
  constexpr double kMinAlpha = 0.002025;  // the specular bricks' domain (slot.json)
  in.perceptualRoughness = fp32(r);
  in.alpha = fp32(r * r);
  in.at = fp32(std::min(1.5 * in.alpha, 1.0));
  in.ab = fp32(std::max(0.5 * in.alpha, kMinAlpha));
  const double tangentAzimuth = ref::kPi / 6.0;
  in.t = {fp32(std::cos(tangentAzimuth)), fp32(std::sin(tangentAzimuth)), 0.0};
}

double mapAlpha(const Lobe& lobe, const ProbeInputs& in) {
  return lobe.kind == LobeKind::Anisotropic ? std::min(in.at, in.ab) : in.alpha;
}

std::vector<GridCell> gridCells(const EnergyGrid& grid) {
  std::vector<GridCell> cells;
  for (double mu : grid.NoV) {
    for (double r : grid.perceptualRoughness) {
      GridCell c;
      c.perceptualRoughness = r;
      // The view vector as the GPU gets it (fp32); the quadrature uses its exact direction.
      c.inputs.v = {fp32(std::sqrt(std::max(0.0, 1.0 - mu * mu))), 0.0, fp32(mu)};
      c.NoV = ref::normalize(c.inputs.v).z;
      setRoughness(c.inputs, r);
      cells.push_back(c);
    }
  }
  return cells;
}

}  // namespace mb::energy
