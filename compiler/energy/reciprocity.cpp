#include "energy/reciprocity.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "validate/sampler.hpp"

namespace mb::energy {
namespace {

struct Pair {
  ProbeInputs forward;  // (v, l); the swapped record exchanges v and l
  bool grazing = false;
};

ref::Vec3 direction(double cosTheta, double phi) {
  double s = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return {s * std::cos(phi), s * std::sin(phi), cosTheta};
}

// Interior pairs: both cosines uniform in [1e-3, 1]. Every fourth pair is grazing: one
// cosine log-uniform in [1e-6, 1e-4], below the n.v clamp. Roughness uniform over the grid's.
std::vector<Pair> randomPairs(const EnergyGrid& grid) {
  SplitMix64 rng(grid.seed);
  const auto [rLo, rHi] = std::minmax_element(grid.perceptualRoughness.begin(), grid.perceptualRoughness.end());
  std::vector<Pair> pairs(grid.reciprocityPairs);
  for (size_t i = 0; i < pairs.size(); ++i) {
    Pair& p = pairs[i];
    p.grazing = i % 4 == 3;
    double a = 1e-3 + (1.0 - 1e-3) * rng.uniform();
    double b =
        p.grazing ? std::exp(std::log(1e-6) + std::log(100.0) * rng.uniform()) : 1e-3 + (1.0 - 1e-3) * rng.uniform();
    if (rng.uniform() < 0.5) std::swap(a, b);
    p.forward.v = direction(a, 2.0 * ref::kPi * rng.uniform());
    p.forward.l = direction(b, 2.0 * ref::kPi * rng.uniform());
    setRoughness(p.forward, *rLo + (*rHi - *rLo) * rng.uniform());
  }
  return pairs;
}

double relative(double a, double b) {
  double scale = std::max(std::abs(a), std::abs(b));
  return scale > 0.0 ? std::abs(a - b) / scale : 0.0;
}

}  // namespace

std::string ReciprocityResult::verdict() const {
  if (!referenceReciprocal()) return "not reciprocal";
  if (!grazingReciprocal()) return "reciprocal for n.v, n.l >= 1e-4 (n.v clamp)";
  return "reciprocal";
}

std::vector<ReciprocityResult> reciprocity(harness::VulkanHarness& gpu, ProbeCache& probes,
                                           const std::vector<Lobe>& lobes, const EnergyGrid& grid,
                                           ProgressSink* progress) {
  const std::vector<Pair> pairs = randomPairs(grid);
  const size_t n = pairs.size();
  // Records 0..n-1 are (v, l), n..2n-1 the same pairs swapped.
  auto recordAt = [&](size_t i) {
    ProbeInputs in = pairs[i % n].forward;
    if (i >= n) std::swap(in.v, in.l);
    return in;
  };
  std::map<std::string, const Brick*> bricks;
  for (const Lobe& lobe : lobes)
    for (const Brick* b : lobe.factors) bricks.emplace(b->id, b);
  std::map<std::string, BrickValues> values;
  for (const auto& [id, b] : bricks) {
    values[id] = sweepBrick(gpu, probes.get(*b), 2 * n, recordAt);
    if (progress) progress->advance();
  }

  std::vector<ReciprocityResult> out;
  for (const Lobe& lobe : lobes) {
    ReciprocityResult r;
    r.lobe = &lobe;
    std::vector<const BrickValues*> factors;
    for (const Brick* b : lobe.factors) factors.push_back(&values.at(b->id));
    auto product = [&](size_t i, bool useGpu) {
      double f = 1.0;
      for (const BrickValues* v : factors) f *= useGpu ? v->gpu[i] : v->reference[i];
      return f;
    };
    for (size_t i = 0; i < n; ++i) {
      double g = product(i, true), gs = product(i + n, true);
      double ref = product(i, false), refs = product(i + n, false);
      if (pairs[i].grazing) {
        ++r.grazingPairs;
        r.grazingGpuAsymmetry = std::max(r.grazingGpuAsymmetry, relative(g, gs));
        r.grazingReferenceAsymmetry = std::max(r.grazingReferenceAsymmetry, relative(ref, refs));
        continue;
      }
      ++r.pairs;
      r.gpuAsymmetry = std::max(r.gpuAsymmetry, relative(g, gs));
      r.referenceAsymmetry = std::max(r.referenceAsymmetry, relative(ref, refs));
      double allowed = productBound(factors, i) + productBound(factors, i + n) + std::abs(ref - refs);
      double diff = std::abs(g - gs);
      if (diff > 0.0) r.maxBoundRatio = std::max(r.maxBoundRatio, allowed > 0.0 ? diff / allowed : INFINITY);
    }
    out.push_back(r);
  }
  return out;
}

}  // namespace mb::energy
