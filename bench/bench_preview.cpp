// The preview's cost (issue 13, item 2): a SIZE x SIZE preview of one material, timed stage by
// stage, REPEATS times in one process:
//
//   environment_ms   the one-time environment build (cube prefilter, SH9, DFG LUT, uploads),
//                    once per process (the in-memory cache makes later builds free);
//   first_gpu_ms     the first renderPreview GPU path: fragment-shader emit + compile, the two
//                    pipelines (lavapipe compiles the shaders there and at the first draw), both
//                    render passes and the GPU tonemap;
//   gpu_ms           the same in later runs (the SPIR-V compile is repeated, lavapipe's JIT is
//                    served by Mesa's shader cache);
//   reference_ms     the CPU reference render (all cores), and compare_ms the comparison.
//
// Usage: mb_bench_preview REPEATS SIZE MATERIAL [ENVIRONMENT]
// Prints JSON with medians over the repeats and every repeat's values; the load average is
// recorded before and after, since the machine is shared.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "bench_stats.hpp"
#include "library/shader_library.hpp"
#include "load/material_desc.hpp"
#include "preview/preview.hpp"

using namespace mb;
using Clock = std::chrono::steady_clock;

namespace {

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

using mb::bench::median;

using mb::bench::loadAverage;

// GPU path of one result: everything renderPreview does except the reference and comparison.
double gpuPathMs(const preview::PreviewResult& r) {
  return r.compileMs + r.pipelineMs + r.renderMs + r.attributesMs + r.tonemapMs;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: mb_bench_preview REPEATS SIZE MATERIAL [ENVIRONMENT]\n";
    return 2;
  }
  const int repeats = std::max(1, std::atoi(argv[1]));
  preview::PreviewOptions options;
  options.size = static_cast<uint32_t>(std::atoi(argv[2]));
  const std::string environment = argc > 4 ? argv[4] : "studio";
  const std::string loadBefore = loadAverage();

  const ShaderLibrary lib = ShaderLibrary::load(ShaderLibrary::defaultRoot());
  const MaterialDesc material = loadMaterialJson(argv[3], lib);
  harness::VulkanHarness gpu;
  auto t0 = Clock::now();
  const preview::PreviewEnvironment env = preview::prepareEnvironment(gpu, lib, environment);
  const double environmentMs = msSince(t0);

  std::vector<double> gpuMs, totalMs, referenceMs, compareMs, renderMs, pipelineMs, compileMs, tonemapMs;
  nlohmann::json runs = nlohmann::json::array();
  bool passed = true;
  for (int i = 0; i < repeats; ++i) {
    t0 = Clock::now();
    const preview::PreviewResult r = preview::renderPreview(gpu, lib, material, options, env);
    const double total = msSince(t0);
    passed = passed && r.passed();
    gpuMs.push_back(gpuPathMs(r));
    totalMs.push_back(total);
    referenceMs.push_back(r.referenceMs);
    compareMs.push_back(r.compareMs);
    renderMs.push_back(r.renderMs + r.attributesMs);
    pipelineMs.push_back(r.pipelineMs);
    compileMs.push_back(r.compileMs);
    tonemapMs.push_back(r.tonemapMs);
    runs.push_back({{"gpu_path_ms", gpuMs.back()},
                    {"compile_ms", r.compileMs},
                    {"pipeline_ms", r.pipelineMs},
                    {"render_ms", r.renderMs},
                    {"attributes_ms", r.attributesMs},
                    {"tonemap_ms", r.tonemapMs},
                    {"reference_ms", r.referenceMs},
                    {"compare_ms", r.compareMs},
                    {"total_ms", total},
                    {"max_error_over_tolerance", r.maxErrorRatio},
                    {"passed", r.passed()}});
  }
  std::vector<double> later(gpuMs.begin() + (gpuMs.size() > 1 ? 1 : 0), gpuMs.end());
  nlohmann::json out{{"material", material.name},
                     {"size", options.size},
                     {"environment", environment},
                     {"device", gpu.deviceName()},
                     {"hardware_threads", std::thread::hardware_concurrency()},
                     {"repeats", repeats},
                     {"environment_build_ms", environmentMs},
                     {"first_gpu_path_ms", gpuMs.front()},
                     {"gpu_path_ms_median_after_first", median(later)},
                     {"pipeline_ms_median", median(pipelineMs)},
                     {"compile_ms_median", median(compileMs)},
                     {"render_both_passes_ms_median", median(renderMs)},
                     {"tonemap_ms_median", median(tonemapMs)},
                     {"reference_ms_median", median(referenceMs)},
                     {"compare_ms_median", median(compareMs)},
                     {"total_ms_median", median(totalMs)},
                     {"passed", passed},
                     {"load_average_before", loadBefore},
                     {"load_average_after", loadAverage()},
                     {"runs", runs}};
  std::cout << out.dump(2) << "\n";
  return passed ? 0 : 1;
}
