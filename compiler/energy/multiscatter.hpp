// Multiple-scattering compensation at f0 = 1: the single-scattering GGX lobe
// (d_ggx * v_smith_ggx_correlated, albedo E from the white furnace on the GPU) times the
// brick with kernel role "multiscatter" (energy_compensation_filament in the shipped library,
// slot.json) run on the GPU with E_dfg = DFG channel 1 from the CPU
// quadrature (common/ibl_reference.hpp dfgIntegrals). The factor is 1 + f0 (1/E_dfg - 1),
// i.e. 1/E_dfg at f0 = 1, so the compensated albedo E * comp should be 1 (Filament sec.
// 5.3.4.7, after Kulla & Conty 2017).
//
// Margin, derived per cell: E_gpu comp - 1 = (E_gpu - E) comp + E (comp - 1/E_dfg) +
// (E - E_dfg) / E_dfg, with E the exact albedo, so
//   |E_gpu comp - 1| <= (bound + 2 conv) comp + E (tol_comp + rnd) + 2 dfgConv / E_dfg
// where bound and conv come from the furnace cell, tol_comp from the brick's tolerance, rnd
// = |1/fp32(E_dfg) - 1/E_dfg| is the rounding of the GPU's input, and
// dfgConv = |dfg(tolerance 1e-10) - dfg(1e-13)| estimates the DFG quadrature's own error.
#pragma once
#include <vector>

#include "energy/white_furnace.hpp"

namespace mb::energy {

struct CompensationCell {
  double NoV = 0, perceptualRoughness = 0;
  double albedo = 0;          // E_gpu, single scattering
  double dfgY = 0;            // E_dfg, CPU quadrature
  double compensation = 0;    // GPU output of the compensation brick
  double compensated = 0;     // albedo * compensation
  double margin = 0;          // derived bound on |compensated - 1|
  double referenceVsDfg = 0;  // A_ref - E_dfg: two independent quadratures of one integral
};

struct CompensationResult {
  std::string brick;  // the brick with kernel role "multiscatter" (energy_compensation_filament)
  std::vector<CompensationCell> cells;
  double maxDeviation() const;  // max |1 - compensated|
  double maxMargin() const;
  bool passed() const;  // every cell within its margin
};

// `ggx`: the furnace result of d_ggx * v_smith_ggx_correlated on `grid`.
CompensationResult multiscatterCompensation(harness::VulkanHarness& gpu, ProbeCache& probes, const ShaderLibrary& lib,
                                            const LobeAlbedo& ggx, const EnergyGrid& grid);

}  // namespace mb::energy
