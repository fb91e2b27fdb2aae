// Runs what the report shows on the device (docs/report.md): per material its permutations
// through validate's probes and bench's cost kernels, per slot bench's run-time-against-error
// measurement, the white furnace of the lobes the materials use, and the DFG LUT with its
// check against the exact integrals. Nothing is built here: every shader comes from
// validate/, emit/bench_probe and lut/.
#pragma once
#include "core/progress_sink.hpp"
#include <ostream>
#include <string>
#include <vector>

#include "permute/permutation.hpp"
#include "report/report_data.hpp"

namespace mb::report {

// The permutations of one material, as the report groups them.
struct MaterialPermutations {
  const MaterialDesc* material = nullptr;
  std::vector<Permutation> permutations;
  std::vector<std::string> notes;  // what was skipped and why
};

// `progress` (may be null) counts one unit per material (its previews) and per permutation,
// and whatever bench, energy and the LUT check add to its total as they go.
ReportData runReport(const ShaderLibrary& lib, harness::VulkanHarness& gpu,
                     const std::vector<MaterialPermutations>& materials, const ReportOptions& options,
                     ProgressSink* progress);

// The lobes of `all` whose every factor brick is among `bricks` (those the reported shaders
// call), in library order.
std::vector<energy::Lobe> lobesUsing(const std::vector<energy::Lobe>& all, const std::vector<std::string>& bricks);

}  // namespace mb::report
