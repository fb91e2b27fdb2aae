// The report's use of the result cache (core/result_cache.hpp): the measured cost of every
// permutation's bench kernels, each slot chart's brick items (cost and error) and each lobe's
// white-furnace albedo are looked up before they are measured and stored after. An entry's key
// holds everything its result depends on: the device and driver (harness deviceIdentity), the
// toolchain, the SPIR-V of the probe and the GLSL of the bench kernels measured, the sample
// domain, tolerances, grid and options; the cache adds the executable's own hash. So an
// edited material or brick misses only its own entries, and a cached cost is a timing from an
// earlier run on this device and driver (docs/report.md "Result cache").
#pragma once
#include "bench_engine/bench_runner.hpp"
#include "core/result_cache.hpp"
#include "energy/brick_sweep.hpp"
#include "energy/white_furnace.hpp"

namespace mb::report {

// Entry kinds: each a folder of the cache and a line of the report's cache table.
inline constexpr const char* kPermutationCostEntries = "permutation-cost";
inline constexpr const char* kBrickItemEntries = "slot-brick";
inline constexpr const char* kLobeAlbedoEntries = "lobe-albedo";

// bench::measurePermutationCost, through the cache.
bench::BenchCost cachedPermutationCost(ResultCache& cache, harness::VulkanHarness& gpu, const ShaderLibrary& lib,
                                       const Permutation& perm, const ProbeProgram& probe,
                                       const bench::CostOptions& options);

// The memo runBench consults for the slot charts' brick items, measured with `options`.
// Refers to its arguments, which must outlive it.
bench::BrickItemMemo brickItemMemo(ResultCache& cache, harness::VulkanHarness& gpu, const ShaderLibrary& lib,
                                   const bench::BenchOptions& options);

// energy::whiteFurnace, through the cache: only the lobes without an entry are integrated.
// Results point into `lobes`; `progress` advances one unit per lobe.
std::vector<energy::LobeAlbedo> cachedWhiteFurnace(ResultCache& cache, harness::VulkanHarness& gpu,
                                                   energy::ProbeCache& probes, const std::vector<energy::Lobe>& lobes,
                                                   const energy::EnergyGrid& grid, ProgressSink* progress);

}  // namespace mb::report
