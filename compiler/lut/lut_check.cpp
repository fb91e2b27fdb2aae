#include "lut/lut_check.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "lut/lut_reference.hpp"

namespace mb::lut {
namespace {

struct TexelResult {
  TexelSum sum;
  std::array<double, kChannels> quad{};
};

}  // namespace

std::vector<uint32_t> checkIndices(uint32_t size, uint32_t grid) {
  std::vector<uint32_t> idx;
  if (grid == 0 || grid >= size) {
    for (uint32_t k = 0; k < size; ++k) idx.push_back(k);
    return idx;
  }
  for (uint32_t k = 0; k < grid; ++k)
    idx.push_back(grid == 1 ? 0 : static_cast<uint32_t>(std::llround(double(k) * (size - 1) / (grid - 1))));
  idx.erase(std::unique(idx.begin(), idx.end()), idx.end());
  return idx;
}

LutCheck checkLut(const ShaderLibrary& lib, const LutTable& gpu, uint32_t grid, bool withQuadrature,
                  ProgressSink* progress) {
  auto t0 = std::chrono::steady_clock::now();
  const bool exactJudged = gpu.samples == 0;
  withQuadrature = withQuadrature || exactJudged;
  const SameSum sameSum(lutBricks(lib));
  const std::vector<uint32_t> axis = checkIndices(gpu.size, grid);
  std::vector<uint64_t> texels;
  for (uint32_t j : axis)
    for (uint32_t i : axis) texels.push_back(static_cast<uint64_t>(j) * gpu.size + i);
  const std::vector<float> inputs = texelInputs(gpu.size);

  // The texel work is independent: spread it over the cores.
  std::vector<TexelResult> results(texels.size());
  if (progress) progress->addToTotal(texels.size());
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t k; (k = next.fetch_add(1)) < texels.size();) {
      const float NoV = inputs[2 * texels[k]], rough = inputs[2 * texels[k] + 1];
      if (!exactJudged) results[k].sum = sameSum.evaluate(NoV, rough, gpu.samples);
      if (withQuadrature) results[k].quad = quadrature(NoV, rough);
      if (progress) progress->advance();
    }
  };
  std::vector<std::thread> pool(std::max(1u, std::thread::hardware_concurrency()));
  for (auto& t : pool) t = std::thread(worker);
  for (auto& t : pool) t.join();

  LutCheck out;
  out.texels = texels.size();
  out.withQuadrature = withQuadrature;
  for (size_t k = 0; k < texels.size(); ++k) {
    for (uint32_t c = 0; c < kChannels; ++c) {
      const double g = gpu.values[texels[k] * kChannels + c];
      if (!std::isfinite(g)) {
        ++out.nonFinite;
        continue;
      }
      const TexelSum& s = results[k].sum;
      const double q = results[k].quad[c];
      double err = 0, bound = 0;
      if (exactJudged) {
        err = std::fabs(g - q);
        bound = c == kChannelCloth ? kClothRelBound * std::fabs(q) + kClothAbsFloor : kExactAbsBound;
      } else {
        err = std::fabs(g - s.value[c]);
        bound = s.bound[c];
        out.sameSum[c].maxAbs = std::max(out.sameSum[c].maxAbs, err);
        out.sameSum[c].meanAbs += err / texels.size();
      }
      out.maxBound[c] = std::max(out.maxBound[c], bound);
      if (err > bound) ++out.failures;
      const double ratio = bound > 0 ? err / bound : (err > 0 ? INFINITY : 0.0);
      if (ratio > out.maxBoundRatio || out.worstTexel < 0) {
        out.maxBoundRatio = std::max(out.maxBoundRatio, ratio);
        out.worstTexel = static_cast<int64_t>(texels[k]);
      }
      if (withQuadrature) {
        const double e = std::fabs(g - q);
        out.quadrature[c].maxAbs = std::max(out.quadrature[c].maxAbs, e);
        out.quadrature[c].meanAbs += e / texels.size();
        out.quadrature[c].maxRel = std::max(out.quadrature[c].maxRel, e / std::max(std::fabs(q), kClothAbsFloor));
      }
    }
  }
  out.cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace mb::lut
