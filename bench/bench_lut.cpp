// DFG LUT generation on the device (lavapipe by default): timestamped GPU time per table
// size, and the error of the table against the exact integrals (and, for the Hammersley
// estimator, against the CPU evaluation of the identical sum). Prints JSON (bench/README.md
// has the command).
//
//   mb_bench_lut REPEATS SIZE:SAMPLES[:GRID[:MAPFILE]]...
//
// SAMPLES 0 is the deterministic quadrature (the default of `matbricks lut`); GRID is the
// checked texels per axis (0: every texel; default 32); MAPFILE, when given, receives the
// per-texel error map as CSV.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <thread>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "bench_stats.hpp"
#include "compile/glsl_compiler.hpp"
#include "lut/lut_check.hpp"
#include "lut/lut_gpu.hpp"
#include "lut/lut_reference.hpp"

using namespace mb;

namespace {

using mb::bench::median;

nlohmann::json channels(const std::array<lut::ChannelError, lut::kChannels>& e) {
  nlohmann::json out = nlohmann::json::object();
  for (uint32_t c = 0; c < lut::kChannels; ++c)
    out[lut::kChannelNames[c]] = {{"max_abs", e[c].maxAbs}, {"mean_abs", e[c].meanAbs}, {"max_rel", e[c].maxRel}};
  return out;
}

// Per-texel error against the exact integrals: i, j, n.v, roughness, then per channel the
// signed error (GPU - exact); for the cloth channel also the relative error.
void writeErrorMap(const std::string& path, const lut::LutTable& t, uint32_t grid) {
  const std::vector<uint32_t> axis = lut::checkIndices(t.size, grid);
  std::vector<std::array<double, lut::kChannels>> exact(axis.size() * axis.size());
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t k; (k = next.fetch_add(1)) < exact.size();)
      exact[k] = lut::quadrature(lut::texelCentre(axis[k % axis.size()], t.size),
                                 lut::texelCentre(axis[k / axis.size()], t.size));
  };
  std::vector<std::thread> pool(std::max(1u, std::thread::hardware_concurrency()));
  for (auto& th : pool) th = std::thread(worker);
  for (auto& th : pool) th.join();
  std::ofstream f(path);
  f << "# matbricks DFG LUT " << t.size << "x" << t.size
    << (t.samples ? ", Hammersley " + std::to_string(t.samples) : ", quadrature")
    << ": GPU minus the exact integrals per texel (bench/bench_lut.cpp)\n";
  f << "i,j,nov,perceptual_roughness,err_dfg_gv_fc,err_dfg_gv,err_cloth,rel_err_cloth\n";
  char buf[160];
  for (size_t k = 0; k < exact.size(); ++k) {
    const uint32_t i = axis[k % axis.size()], j = axis[k / axis.size()];
    double e[lut::kChannels];
    for (uint32_t c = 0; c < lut::kChannels; ++c) e[c] = double(t.at(i, j, c)) - exact[k][c];
    std::snprintf(buf, sizeof buf, "%u,%u,%.6g,%.6g,%.2e,%.2e,%.2e,%.2e\n", i, j, lut::texelCentre(i, t.size),
                  lut::texelCentre(j, t.size), e[0], e[1], e[2],
                  e[2] / std::max(std::fabs(exact[k][2]), lut::kClothAbsFloor));
    f << buf;
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: mb_bench_lut REPEATS SIZE:SAMPLES[:GRID[:MAPFILE]]...\n");
    return 2;
  }
  const int repeats = std::max(1, std::atoi(argv[1]));
  ShaderLibrary lib = ShaderLibrary::load(ShaderLibrary::defaultRoot());
  harness::VulkanHarness gpu;
  nlohmann::json runs = nlohmann::json::array();
  for (int a = 2; a < argc; ++a) {
    std::vector<std::string> spec;
    for (std::string rest = argv[a];;) {
      const size_t colon = rest.find(':');
      spec.push_back(rest.substr(0, colon));
      if (colon == std::string::npos) break;
      rest = rest.substr(colon + 1);
    }
    const uint32_t size = static_cast<uint32_t>(std::stoul(spec.at(0)));
    const uint32_t samples = static_cast<uint32_t>(std::stoul(spec.at(1)));
    const uint32_t grid = spec.size() > 2 ? static_cast<uint32_t>(std::stoul(spec[2])) : 32;
    std::vector<double> gpuMs, warmupMs, compileMs;
    lut::GpuLut last;
    for (int r = 0; r < repeats; ++r) {
      last = lut::generateDfgLutOnGpu(gpu, lib, size, samples);
      gpuMs.push_back(last.gpuMs);
      warmupMs.push_back(last.warmupGpuMs);
      compileMs.push_back(last.compileMs);
    }
    lut::LutCheck check = lut::checkLut(lib, last.table, grid, true);
    if (spec.size() > 3) writeErrorMap(spec[3], last.table, grid);
    const double texelSamples = double(size) * size * samples;
    runs.push_back({{"size", size},
                    {"samples", samples},
                    {"repeats", repeats},
                    {"gpu_ms_median", median(gpuMs)},
                    {"gpu_ms_all", gpuMs},
                    {"ns_per_texel_sample", median(gpuMs) * 1e6 / texelSamples},
                    {"warmup_dispatch_gpu_ms_median", median(warmupMs)},
                    {"compile_ms_median", median(compileMs)},
                    {"gpu_timestamps", last.gpuTimestamps},
                    {"checked_texels", check.texels},
                    {"estimator", samples ? "hammersley" : "quadrature"},
                    {"judged_against", samples ? "same_sum" : "exact"},
                    {"max_error_over_bound", check.maxBoundRatio},
                    {"failures", check.failures},
                    {"vs_same_sum", samples ? channels(check.sameSum) : nlohmann::json(nullptr)},
                    {"vs_quadrature", channels(check.quadrature)}});
  }
  nlohmann::json out{{"device", gpu.deviceName()}, {"toolchain", toolchainVersion()}, {"runs", runs}};
  std::cout << out.dump(2) << "\n";
  return 0;
}
