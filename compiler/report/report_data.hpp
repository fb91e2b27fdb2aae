// What `matbricks report` shows (docs/report.md), as data: every number comes from the runs of
// this invocation on the device (validate's probes, bench's kernels and charts, energy's white
// furnace, the LUT generator and its check); report_html.hpp only formats it.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench_engine/bench_runner.hpp"
#include "energy/energy_grid.hpp"
#include "energy/white_furnace.hpp"
#include "lut/lut_check.hpp"
#include "lut/lut_gpu.hpp"
#include "report/preview_section.hpp"
#include "validate/validation.hpp"

namespace mb::report {

struct ReportOptions {
  uint64_t samples = 4096;  // validation samples per permutation (validate's default)
  uint64_t seed = 1;
  // ns per evaluation of each permutation and each slot's bricks: bench's method with fewer
  // repeats and shorter dispatches than `bench` (a report must stay quick; docs/report.md).
  bench::CostOptions cost = quickCost();
  bool slots = true;
  // Error samples per brick of the slot charts: some ground truths are numerical integrals
  // (the sphere and tube energy normalizations take ~20-50 ms per sample on this machine), so
  // bench's 4096 would make the charts take many minutes. The max error is then over fewer
  // samples (the chart's subtitle says how many).
  uint64_t slotSamples = 256;
  std::vector<std::string> slotFilter;  // empty: every slot the permutations' shaders call
  bool energy = true;
  energy::EnergyGrid grid = reportGrid();
  bool lut = true;
  uint32_t lutSize = 64;
  uint32_t lutCheckGrid = 16;  // texels per axis judged against the exact integrals
  PreviewRenderer previews;    // empty: the previews section says none were rendered

  static bench::CostOptions quickCost();
  // energy's coarse grid in roughness, its fine grid in n.v (the plot's x axis).
  static energy::EnergyGrid reportGrid();
};

struct PermutationRow {
  ValidationRecord validation;  // error metrics, compile time, SPIR-V instructions
  bench::CostMeasurement cost;  // ns per evaluation of its bench kernel, with its interval
  double staticCost = 0;        // bench_engine/static_cost.hpp, fp32 FMA issue slots per evaluation
  std::vector<std::string> bricks;
};

struct MaterialSection {
  std::string name, model, sourceFile;
  std::vector<std::string> notes;  // permutations skipped and why
  PreviewSet previews;
  std::vector<PermutationRow> permutations;
};

struct EnergySection {
  energy::EnergyGrid grid;
  std::vector<energy::Lobe> lobes;
  std::vector<energy::LobeAlbedo> furnace;  // parallel to lobes; points into it
  EnergySection() = default;
  EnergySection(const EnergySection&) = delete;
  EnergySection& operator=(const EnergySection&) = delete;
};

struct LutSection {
  lut::GpuLut generated;
  lut::LutCheck check;
};

struct SectionTime {
  std::string section;
  double seconds = 0;
};

struct ReportData {
  std::string device, toolchain, command;
  std::vector<MaterialSection> materials;
  std::optional<bench::BenchReport> slots;
  std::unique_ptr<EnergySection> energy;
  std::optional<LutSection> lut;
  std::vector<SectionTime> times;
  bool layerMessages = false;
  // Why the report's checks failed (empty: all passed): a permutation outside its tolerance, a
  // lobe whose GPU albedo misses its reference, the LUT outside its promised accuracy.
  std::vector<std::string> failures() const;
};

}  // namespace mb::report
