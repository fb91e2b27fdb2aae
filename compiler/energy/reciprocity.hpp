// Reciprocity (Helmholtz): f(v, l) = f(l, v). Every lobe is evaluated on the GPU at random
// pairs (v, l) and at the swapped pairs (l, v), in one probe run per brick.
//
// Interior pairs (n.v, n.l in [1e-3, 1]): a lobe whose double reference is symmetric there
// (relative asymmetry <= 1e-12, double rounding) must be symmetric on the GPU within
//   |g(v,l) - g(l,v)| <= b(v,l) + b(l,v) + |r(v,l) - r(l,v)|,
// b being the product bound of white_furnace.hpp; otherwise it is a GPU bug and the check
// fails. Grazing pairs (one cosine in [1e-6, 1e-4]) probe the shading geometry itself:
// makeGeometry clamps n.v to MB_MIN_N_DOT_V = 1e-4 (common.glsl, after Filament) but n.l only
// to 0, so any lobe that depends on n.v and n.l is not reciprocal below 1e-4, by design.
#pragma once
#include <string>
#include <vector>

#include "core/progress_sink.hpp"
#include "energy/energy_grid.hpp"

namespace mb::energy {

struct ReciprocityResult {
  const Lobe* lobe = nullptr;
  uint64_t pairs = 0, grazingPairs = 0;
  // Max relative asymmetry |f(v,l) - f(l,v)| / max(|f(v,l)|, |f(l,v)|).
  double gpuAsymmetry = 0, referenceAsymmetry = 0;                // interior pairs
  double grazingGpuAsymmetry = 0, grazingReferenceAsymmetry = 0;  // grazing pairs
  double maxBoundRatio = 0;                                       // interior: |g(v,l) - g(l,v)| / allowed
  bool referenceReciprocal() const { return referenceAsymmetry <= kSymmetric; }
  bool grazingReciprocal() const { return grazingReferenceAsymmetry <= kSymmetric; }
  bool passed() const { return !referenceReciprocal() || maxBoundRatio <= 1.0; }
  std::string verdict() const;
  static constexpr double kSymmetric = 1e-12;
};

// `progress` advances one unit per distinct brick of the lobes, as each is swept (the caller
// announced them).
std::vector<ReciprocityResult> reciprocity(harness::VulkanHarness& gpu, ProbeCache& probes,
                                           const std::vector<Lobe>& lobes, const EnergyGrid& grid,
                                           ProgressSink* progress = nullptr);

}  // namespace mb::energy
