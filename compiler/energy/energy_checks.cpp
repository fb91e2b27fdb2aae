#include "energy/energy_checks.hpp"

#include <chrono>
#include <set>
#include <string>

namespace mb::energy {

void runEnergyChecks(const ShaderLibrary& lib, harness::VulkanHarness& gpu, const EnergyGrid& grid,
                     EnergyReport& report, ProgressSink* progress) {
  auto t0 = std::chrono::steady_clock::now();
  report.device = gpu.deviceName();
  report.grid = grid;
  report.lobes = energyLobes(lib);
  report.dfgLobe = dfgLobe(report.lobes, lib);
  ProbeCache probes(lib);
  if (progress) {
    // Announced up front, so that the ETA holds: a unit per lobe (white furnace), one for the
    // compensation, one per distinct brick (reciprocity).
    std::set<std::string> bricks;
    for (const Lobe& lobe : report.lobes)
      for (const Brick* b : lobe.factors) bricks.insert(b->id);
    progress->addToTotal(report.lobes.size() + 1 + bricks.size());
  }
  report.furnace = whiteFurnace(gpu, probes, report.lobes, grid, progress);
  for (const LobeAlbedo& a : report.furnace)
    if (a.lobe == report.dfgLobe) report.compensation = multiscatterCompensation(gpu, probes, lib, a, grid);
  if (progress) progress->advance();
  report.reciprocity = reciprocity(gpu, probes, report.lobes, grid, progress);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<std::string> EnergyReport::failures() const {
  std::vector<std::string> f;
  for (const LobeAlbedo& a : furnace) {
    if (!a.gpuMatchesReference())
      f.push_back(a.lobe->name + ": GPU albedo differs from the reference beyond the derived bound");
    if (a.lobe->expectation == Expectation::Conserving && a.exceedsOne())
      f.push_back(a.lobe->name + ": albedo above 1 for a lobe bounded by 1");
  }
  if (!compensation.passed()) f.push_back("multiscatter compensation outside its margin");
  for (const ReciprocityResult& r : reciprocity)
    if (!r.passed()) f.push_back(r.lobe->name + ": GPU not reciprocal where the reference is");
  return f;
}

}  // namespace mb::energy
