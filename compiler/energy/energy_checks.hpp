// The energy and physics checks of issue 6 (DESIGN.md "Energy"): white furnace of every
// lobe, multiple-scattering compensation, reciprocity; and how the results are rendered
// (text, JSON, Markdown for docs/energy.md).
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "energy/multiscatter.hpp"
#include "energy/reciprocity.hpp"
#include "energy/white_furnace.hpp"

namespace mb::energy {

struct EnergyReport {
  std::string device;
  EnergyGrid grid;
  std::vector<Lobe> lobes;
  std::vector<LobeAlbedo> furnace;  // parallel to lobes
  const Lobe* dfgLobe = nullptr;    // energy::dfgLobe, in `lobes`
  CompensationResult compensation;
  std::vector<ReciprocityResult> reciprocity;  // parallel to lobes
  double seconds = 0;
  // Why the run fails (empty when it passes): a GPU integral outside its derived bound, a
  // lobe that theory bounds by 1 above 1, compensation outside its margin, a GPU asymmetry
  // where the reference is symmetric.
  std::vector<std::string> failures() const;
  EnergyReport() = default;
  EnergyReport(const EnergyReport&) = delete;  // results point into `lobes`
  EnergyReport& operator=(const EnergyReport&) = delete;
};

// Fills `report` (not returned by value: its results point into report.lobes).
void runEnergyChecks(const ShaderLibrary& lib, harness::VulkanHarness& gpu, const EnergyGrid& grid,
                     EnergyReport& report, ProgressSink* progress = nullptr);

nlohmann::json energyJson(const EnergyReport& report);
std::string energyText(const EnergyReport& report);
std::string energyMarkdown(const EnergyReport& report, const std::string& command);

}  // namespace mb::energy
