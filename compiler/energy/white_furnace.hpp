// White furnace: the directional albedo A(v) = Int f(v, l) (n.l) d(omega_l) of every lobe
// (F = 1), integrated from GPU evaluations of its bricks and, at the same fp32 inputs, from
// their double references, over the (n.v, roughness) grid.
//
// A lobe is a product of brick probes (D x V): each brick runs as its own probe over the
// quadrature nodes and the product is formed on the CPU in double from the fp32 GPU outputs,
// which differs from a shader's fused D * V by one fp32 rounding (6e-8 relative).
//
// Bound on |A_gpu - A_ref|, derived: every node value of every brick lies within that brick's
// validated tolerance t_k = abs + rel |ref| + conditioning (manifest + runProbe), so the
// product lies within sum_k t_k prod_{j<k} |ref_j| prod_{j>k} |gpu_j| (telescoping), and the
// integral within the weighted sum of that (weights are positive and shared by both sides).
// Nodes where a brick misses its own tolerance are counted (they would void the bound).
//
// Quadrature error: estimated per cell as |A_ref(N) - A_ref(N/2)|, the references integrated
// again at half the resolution in both theta_h and phi (CPU only; i.e. the check of doubling
// N/2 -> N). If halving the resolution at least doubles the error, e(N) <= |A(N) - A(N/2)|;
// the checks allow twice that.
#pragma once
#include <vector>

#include "core/progress_sink.hpp"
#include "energy/energy_grid.hpp"

namespace mb::energy {

struct AlbedoCell {
  double NoV = 0, perceptualRoughness = 0;
  double gpu = 0, reference = 0;
  double bound = 0;        // derived bound on |gpu - reference|
  double convergence = 0;  // |A_ref(N) - A_ref(N/2)|
};

struct LobeAlbedo {
  const Lobe* lobe = nullptr;
  std::vector<AlbedoCell> cells;  // NoV-major, as gridCells
  uint64_t nodes = 0;             // quadrature nodes over the whole grid
  uint64_t outsideTolerance = 0;  // node values where a brick missed its own tolerance
  double gpuMs = 0;

  const AlbedoCell& maxCell() const;  // largest GPU albedo
  double maxMismatchRatio() const;    // max |gpu - ref| / bound
  double maxConvergence() const;
  bool gpuMatchesReference() const;  // every cell within its bound, no node outside
  // GPU albedo above 1 by more than the bound plus twice the quadrature estimate somewhere.
  bool exceedsOne() const;
};

// One result per lobe, in the order of `lobes`; `progress` advances one unit per lobe (the
// caller announced them).
std::vector<LobeAlbedo> whiteFurnace(harness::VulkanHarness& gpu, ProbeCache& probes, const std::vector<Lobe>& lobes,
                                     const EnergyGrid& grid, ProgressSink* progress = nullptr);

}  // namespace mb::energy
