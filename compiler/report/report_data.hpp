// What `matbricks report` shows (docs/report.md), as data: every number comes from the runs of
// this invocation on the device (validate's probes, bench's kernels and charts, energy's white
// furnace, the LUT generator and its check); report_html.hpp only formats it.
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench_engine/bench_runner.hpp"
#include "bench_engine/light_methods.hpp"
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
  // The area lights' methods on one chart (bench_engine/light_methods.hpp), for the first
  // reported material whose model shades area lights, over this many lights per method.
  bool lightMethods = true;
  int lightMethodLights = 100;
  bool lut = true;
  uint32_t lutSize = 64;
  uint32_t lutCheckGrid = 16;  // texels per axis judged against the exact integrals
  PreviewRenderer previews;    // empty: the previews section says none were rendered
  // The result cache's folder (core/result_cache.hpp, report/result_memo.hpp): costs, slot
  // items and albedos measured by an earlier run on this device are read from it. Empty: every
  // result is measured in this run.
  std::filesystem::path resultCacheDir;

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

struct LightMethodsSection {
  std::string material;  // whose permutations were timed
  std::vector<bench::LightMethodRow> rows;
  int repeats = 0;
};

struct LutSection {
  lut::GpuLut generated;
  lut::LutCheck check;
};

struct SectionTime {
  std::string section;
  double seconds = 0;
};

// How many results of one kind came from the result cache.
struct CacheUse {
  std::string what;       // "permutation costs", ...
  uint64_t cached = 0;    // read from the cache
  uint64_t total = 0;     // cached + measured in this run
  uint64_t rejected = 0;  // entries found damaged or foreign, measured again
};

struct ReportData {
  std::string device, toolchain, command;
  std::vector<MaterialSection> materials;
  std::optional<bench::BenchReport> slots;
  std::unique_ptr<EnergySection> energy;
  std::optional<LightMethodsSection> lightMethods;
  std::optional<LutSection> lut;
  std::vector<SectionTime> times;
  std::string resultCacheDir;      // empty: the result cache was off
  std::vector<CacheUse> cacheUse;  // per kind of entry, when the cache was on
  bool layerMessages = false;
  // Why the report's checks failed (empty: all passed): a permutation outside its tolerance, a
  // lobe whose GPU albedo misses its reference, the LUT outside its promised accuracy.
  std::vector<std::string> failures() const;
};

}  // namespace mb::report
