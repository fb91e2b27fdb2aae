// DFG LUT generation on the device (lavapipe by default): timestamped GPU time per table
// size, and the error of the table against the CPU evaluation of the identical sum and
// against the high-accuracy quadrature. Prints JSON (bench/README.md has the command).
//
//   mb_bench_lut REPEATS SIZE:SAMPLES...
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "compile/glsl_compiler.hpp"
#include "lut/lut_check.hpp"
#include "lut/lut_gpu.hpp"

using namespace mb;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

nlohmann::json channels(const std::array<lut::ChannelError, lut::kChannels>& e) {
  nlohmann::json out = nlohmann::json::object();
  for (uint32_t c = 0; c < lut::kChannels; ++c)
    out[lut::kChannelNames[c]] = {{"max_abs", e[c].maxAbs}, {"mean_abs", e[c].meanAbs}};
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: mb_bench_lut REPEATS SIZE:SAMPLES...\n");
    return 2;
  }
  const int repeats = std::max(1, std::atoi(argv[1]));
  ShaderLibrary lib = ShaderLibrary::load(ShaderLibrary::defaultRoot());
  harness::VulkanHarness gpu;
  nlohmann::json runs = nlohmann::json::array();
  for (int a = 2; a < argc; ++a) {
    std::string spec = argv[a];
    const uint32_t size = static_cast<uint32_t>(std::stoul(spec.substr(0, spec.find(':'))));
    const uint32_t samples = static_cast<uint32_t>(std::stoul(spec.substr(spec.find(':') + 1)));
    std::vector<double> gpuMs, warmupMs, compileMs;
    lut::GpuLut last;
    for (int r = 0; r < repeats; ++r) {
      last = lut::generateDfgLutOnGpu(gpu, lib, size, samples);
      gpuMs.push_back(last.gpuMs);
      warmupMs.push_back(last.warmupGpuMs);
      compileMs.push_back(last.compileMs);
    }
    lut::LutCheck check = lut::checkLut(last.table, 32, true);
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
                    {"vs_same_sum", {{"channels", channels(check.sameSum)},
                                     {"max_error_over_bound", check.maxBoundRatio},
                                     {"failures", check.failures}}},
                    {"vs_quadrature", channels(check.quadrature)}});
  }
  nlohmann::json out{{"device", gpu.deviceName()}, {"toolchain", toolchainVersion()}, {"runs", runs}};
  std::cout << out.dump(2) << "\n";
  return 0;
}
