// The preview environments (docs/environments.md): build time of each environment's cube on
// the device (lavapipe by default), uncached, and the Monte-Carlo noise of the prefiltered
// levels against the sample count, measured in double (the GPU kernel computes the same sum
// to fp32 rounding: tests/test_environment.cpp). Prints JSON (bench/README.md has the command).
//
//   mb_bench_environment [BASE_SIZE [REPEATS]]
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <thread>

#include "bench_stats.hpp"
#include "harness/vulkan_harness.hpp"
#include "library/shader_library.hpp"
#include "preview/environment.hpp"
#include "preview/environment_cube.hpp"
#include "preview/environment_prefilter.hpp"
#include "preview/environment_reference.hpp"
#include "preview/environment_sh.hpp"

using namespace mb;
using namespace mb::preview;

namespace {

constexpr uint32_t kConvergedSamples = 64 * kPrefilterSamples;
constexpr uint32_t kTexelsPerLevel = 48;

using mb::bench::median;

// Max and mean over `texels` of max_c |estimate(N) - estimate(64 x 1024)| / max_c estimate(64 x 1024).
nlohmann::json noise(const std::string& name, uint32_t baseSize, const std::vector<uint32_t>& counts) {
  const uint32_t levels = [&] {
    uint32_t n = 1;
    while ((baseSize >> n) > 0) ++n;
    return n;
  }();
  nlohmann::json out = nlohmann::json::array();
  for (uint32_t level = 1; level < levels; ++level) {
    const uint32_t size = baseSize >> level;
    const double r = levelRoughness(level, levels - 1), alpha = r * r;
    std::mt19937 rng(level);
    std::vector<std::array<double, 3>> dirs;
    for (uint32_t k = 0; k < kTexelsPerLevel; ++k)
      dirs.push_back(cubeTexelDirection(rng() % 6, rng() % size, rng() % size, size));
    std::vector<std::array<double, 3>> converged(dirs.size());
    std::vector<std::vector<std::array<double, 3>>> estimates(counts.size(), converged);
    std::atomic<size_t> next{0};
    auto worker = [&] {
      for (size_t k; (k = next.fetch_add(1)) < dirs.size();) {
        converged[k] = prefilterReference(name, dirs[k], alpha, kConvergedSamples, peakSamples(kConvergedSamples));
        for (size_t c = 0; c < counts.size(); ++c)
          estimates[c][k] = prefilterReference(name, dirs[k], alpha, counts[c], peakSamples(counts[c]));
      }
    };
    std::vector<std::thread> pool(std::max(1u, std::thread::hardware_concurrency()));
    for (auto& th : pool) th = std::thread(worker);
    for (auto& th : pool) th.join();
    nlohmann::json row = {{"level", level}, {"size", size}, {"roughness", r}};
    for (size_t c = 0; c < counts.size(); ++c) {
      double worst = 0, sum = 0;
      for (size_t k = 0; k < dirs.size(); ++k) {
        const double scale = std::max({converged[k][0], converged[k][1], converged[k][2]});
        double e = 0;
        for (int ch = 0; ch < 3; ++ch) e = std::max(e, std::abs(estimates[c][k][ch] - converged[k][ch]) / scale);
        worst = std::max(worst, e);
        sum += e;
      }
      row["samples_" + std::to_string(counts[c])] = {{"max_rel", worst}, {"mean_rel", sum / dirs.size()}};
    }
    out.push_back(row);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const uint32_t baseSize = argc > 1 ? static_cast<uint32_t>(std::atoi(argv[1])) : 128;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
  harness::VulkanHarness gpu;
  const ShaderLibrary lib = ShaderLibrary::load(ShaderLibrary::defaultRoot());
  nlohmann::json out = {{"device", gpu.deviceName()},
                        {"base_size", baseSize},
                        {"samples", kPrefilterSamples},
                        {"converged_samples", kConvergedSamples},
                        {"texels_per_level", kTexelsPerLevel}};
  for (const std::string& name : environmentNames()) {
    const std::string glsl = prefilterKernelGlsl(lib, name, kPrefilterSamples);
    std::vector<double> ms;
    std::vector<CubeLevel> levels;
    for (int r = 0; r < repeats; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      levels = prefilterOnGpu(gpu, glsl, name, baseSize);  // compile + run, never cached
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    const auto t0 = std::chrono::steady_clock::now();
    double sh[9][3];
    projectSh9(levels.front(), sh);
    const double shMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    out["environments"][name] = {{"build_ms", ms},
                                 {"build_ms_median", median(ms)},
                                 {"sh9_ms", shMs},
                                 // L00 Y00 is the map's mean radiance (green channel).
                                 {"mean_radiance", sh[0][1] * 0.5 / std::sqrt(M_PI)},
                                 {"noise", noise(name, baseSize, {256, 1024, 4096})}};
    std::cerr << name << ": " << median(ms) << " ms\n";
  }
  std::cout << out.dump(2) << "\n";
  return gpu.validationMessages().empty() ? 0 : 1;
}
