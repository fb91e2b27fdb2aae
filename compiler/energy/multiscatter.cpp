#include "energy/multiscatter.hpp"

#include <algorithm>
#include <cmath>

#include "common/ibl_reference.hpp"

namespace mb::energy {
double CompensationResult::maxDeviation() const {
  double m = 0.0;
  for (const auto& c : cells) m = std::max(m, std::abs(1.0 - c.compensated));
  return m;
}

double CompensationResult::maxMargin() const {
  double m = 0.0;
  for (const auto& c : cells) m = std::max(m, c.margin);
  return m;
}

bool CompensationResult::passed() const {
  for (const auto& c : cells)
    if (!(std::abs(1.0 - c.compensated) <= c.margin)) return false;
  return !cells.empty();
}

CompensationResult multiscatterCompensation(harness::VulkanHarness& gpu, ProbeCache& probes, const ShaderLibrary& lib,
                                            const LobeAlbedo& ggx, const EnergyGrid& grid) {
  // The brick the check is about is the one that takes its kernel role (slot.json).
  const Brick* brick = lib.brickForKernelRole("multiscatter");
  if (!brick) return {};
  const std::vector<GridCell> cells = gridCells(grid);
  std::vector<double> dfg(cells.size()), dfgConv(cells.size());
  for (size_t c = 0; c < cells.size(); ++c) {
    // The adaptive DFG at its default tolerance (1e-10), and its distance to a 1000x tighter
    // run as the estimate of its own error.
    dfg[c] = ref::dfgIntegrals(cells[c].NoV, cells[c].inputs.alpha).gv;
    dfgConv[c] = std::abs(dfg[c] - ref::dfgIntegrals(cells[c].NoV, cells[c].inputs.alpha, 1e-13).gv);
  }
  BrickValues comp = sweepBrick(gpu, probes.get(*brick), cells.size(), [&](size_t c) {
    ProbeInputs in;
    in.f0 = ref::splat(1.0);
    in.dfgY = dfg[c];
    return in;
  });

  CompensationResult r;
  r.brick = brick->id;
  for (size_t c = 0; c < cells.size(); ++c) {
    const AlbedoCell& a = ggx.cells[c];
    CompensationCell m;
    m.NoV = a.NoV;
    m.perceptualRoughness = a.perceptualRoughness;
    m.albedo = a.gpu;
    m.dfgY = static_cast<float>(dfg[c]);  // what the GPU was given
    m.compensation = comp.gpu[c];
    m.compensated = m.albedo * m.compensation;
    // The comp term also carries the fp32 rounding of E_dfg on its way to the GPU.
    double dfgRounding = std::abs(1.0 / m.dfgY - 1.0 / dfg[c]);
    m.margin = (a.bound + 2.0 * a.convergence) * m.compensation + a.reference * (comp.tolerance[c] + dfgRounding) +
               2.0 * dfgConv[c] / dfg[c];
    m.referenceVsDfg = a.reference - dfg[c];
    r.cells.push_back(m);
  }
  return r;
}

}  // namespace mb::energy
