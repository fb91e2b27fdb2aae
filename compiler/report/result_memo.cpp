#include "report/result_memo.hpp"

#include <cstdio>

#include "bench_engine/result_codec.hpp"
#include "core/content_hash.hpp"
#include "emit/bench_probe.hpp"

namespace mb::report {
namespace {

using nlohmann::json;

// Doubles in a key as exact hex floats.
std::string hex(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

std::string domainText(const SampleDomain& d) {
  std::string s;
  for (const auto& [name, r] : d.ranges) s += name + "=" + hex(r.lo) + "," + hex(r.hi) + ";";
  return s + "NoV=" + hex(d.geometry.NoV.lo) + "," + hex(d.geometry.NoV.hi) + ";NoL=" + hex(d.geometry.NoL.lo) + "," +
         hex(d.geometry.NoL.hi);
}

std::string costText(const bench::CostOptions& o) {
  return "repeats=" + std::to_string(o.repeats) + ";records=" + std::to_string(o.records) +
         ";iterations=" + std::to_string(o.iterations) + ";target=" + hex(o.targetDispatchMs) +
         ";max=" + hex(o.maxDispatchMs) + ";seed=" + std::to_string(o.seed) +
         ";opt=" + optimizationCacheToken(o.optimization);
}

std::string spirvText(const std::vector<uint32_t>& spirv) {
  return "spirv=" + contentHash(spirv.data(), spirv.size() * sizeof(uint32_t));
}

std::string toleranceText(const Tolerance& t) { return "tolerance=" + hex(t.abs) + "," + hex(t.rel); }

// What a cost measurement depends on: the device, the toolchain that compiles the bench
// kernels, the kernels' source at the starting iterations (calibration only changes the loop
// count), the probe's SPIR-V and sample domain (the inputs) and the options.
std::vector<std::string> costKey(harness::VulkanHarness& gpu, const ProbeProgram& probe,
                                 const std::function<EmittedShader(const BenchProbeOptions&)>& emit,
                                 const bench::CostOptions& o) {
  return {gpu.deviceIdentity(),
          toolchainVersion(),
          spirvText(probe.compiled.spirv),
          emit({bench::kStartIterations, false}).glsl,
          emit({bench::kStartIterations, true}).glsl,
          domainText(probe.domain),
          costText(o)};
}

// Decodes a hit, or rejects it (a well-formed entry of the wrong shape) and gives nothing.
template <class T, class Decode>
std::optional<T> decoded(ResultCache& cache, const char* kind, const std::optional<json>& hit, Decode decode) {
  if (!hit) return std::nullopt;
  try {
    return decode(*hit);
  } catch (const std::exception&) {
    cache.reject(kind);
    return std::nullopt;
  }
}

json cacheJson(const energy::LobeAlbedo& a) {
  json cells = json::array();
  for (const auto& c : a.cells)
    cells.push_back({jsonNumber(c.NoV), jsonNumber(c.perceptualRoughness), jsonNumber(c.gpu), jsonNumber(c.reference),
                     jsonNumber(c.bound), jsonNumber(c.convergence)});
  return {
      {"cells", cells}, {"nodes", a.nodes}, {"outside_tolerance", a.outsideTolerance}, {"gpu_ms", jsonNumber(a.gpuMs)}};
}

energy::LobeAlbedo lobeAlbedoFromCache(const json& j, const energy::Lobe& lobe) {
  energy::LobeAlbedo a;
  a.lobe = &lobe;
  for (const auto& c : j.at("cells"))
    a.cells.push_back({numberFromJson(c.at(0)), numberFromJson(c.at(1)), numberFromJson(c.at(2)),
                       numberFromJson(c.at(3)), numberFromJson(c.at(4)), numberFromJson(c.at(5))});
  a.nodes = j.at("nodes").get<uint64_t>();
  a.outsideTolerance = j.at("outside_tolerance").get<uint64_t>();
  a.gpuMs = numberFromJson(j.at("gpu_ms"));
  return a;
}

std::vector<std::string> lobeKey(harness::VulkanHarness& gpu, energy::ProbeCache& probes, const energy::Lobe& lobe,
                                 const energy::EnergyGrid& grid) {
  std::vector<std::string> key{gpu.deviceIdentity(), toolchainVersion(), lobe.name,
                               std::to_string(static_cast<int>(lobe.kind)), std::to_string(static_cast<int>(lobe.map))};
  for (const Brick* b : lobe.factors) {
    const ProbeProgram& p = probes.get(*b);
    key.push_back(b->id + ":" + spirvText(p.compiled.spirv) + ":" + toleranceText(p.tolerance));
  }
  std::string g = "NoV=";
  for (double v : grid.NoV) g += hex(v) + ",";
  g += ";roughness=";
  for (double v : grid.perceptualRoughness) g += hex(v) + ",";
  g += ";panels=" + std::to_string(grid.resolution.thetaPanels) + "," + std::to_string(grid.resolution.phiPanels) +
       ";pairs=" + std::to_string(grid.reciprocityPairs) + ";seed=" + std::to_string(grid.seed);
  key.push_back(g);
  return key;
}

}  // namespace

bench::BenchCost cachedPermutationCost(ResultCache& cache, harness::VulkanHarness& gpu, const ShaderLibrary& lib,
                                       const Permutation& perm, const ProbeProgram& probe,
                                       const bench::CostOptions& options) {
  if (!cache.enabled()) return bench::measurePermutationCost(gpu, lib, perm, probe, options);
  const auto key = costKey(
      gpu, probe, [&](const BenchProbeOptions& k) { return emitPermutationBenchProbe(lib, perm, k); }, options);
  if (auto hit = decoded<bench::BenchCost>(cache, kPermutationCostEntries, cache.load(kPermutationCostEntries, key),
                                           bench::benchCostFromCache))
    return *hit;
  bench::BenchCost cost = bench::measurePermutationCost(gpu, lib, perm, probe, options);
  cache.store(kPermutationCostEntries, key, bench::cacheJson(cost));
  return cost;
}

bench::BrickItemMemo brickItemMemo(ResultCache& cache, harness::VulkanHarness& gpu, const ShaderLibrary& lib,
                                   const bench::BenchOptions& options) {
  // The item's error is over `samples` seeded records, judged against the probe's tolerance.
  auto key = [&gpu, &lib, &options](const Brick& b, const ProbeProgram& probe) {
    std::vector<std::string> k = costKey(
        gpu, probe, [&](const BenchProbeOptions& o) { return emitBrickBenchProbe(lib, b, o); }, options.cost);
    k.push_back(b.id);
    k.push_back(toleranceText(probe.tolerance));
    k.push_back("samples=" + std::to_string(options.samples) + ";seed=" + std::to_string(options.seed));
    return k;
  };
  bench::BrickItemMemo memo;
  memo.find = [&cache, key](const Brick& b, const ProbeProgram& probe) {
    if (!cache.enabled()) return std::optional<bench::BenchItem>();
    return decoded<bench::BenchItem>(cache, kBrickItemEntries, cache.load(kBrickItemEntries, key(b, probe)),
                                     bench::benchItemFromCache);
  };
  memo.keep = [&cache, key](const Brick& b, const ProbeProgram& probe, const bench::BenchItem& item) {
    if (cache.enabled()) cache.store(kBrickItemEntries, key(b, probe), bench::cacheJson(item));
  };
  return memo;
}

std::vector<energy::LobeAlbedo> cachedWhiteFurnace(ResultCache& cache, harness::VulkanHarness& gpu,
                                                   energy::ProbeCache& probes, const std::vector<energy::Lobe>& lobes,
                                                   const energy::EnergyGrid& grid, ProgressSink* progress) {
  if (!cache.enabled()) return energy::whiteFurnace(gpu, probes, lobes, grid, progress);
  std::vector<energy::LobeAlbedo> out(lobes.size());
  std::vector<energy::Lobe> todo;
  std::vector<size_t> todoAt;
  std::vector<std::vector<std::string>> keys(lobes.size());
  for (size_t i = 0; i < lobes.size(); ++i) {
    keys[i] = lobeKey(gpu, probes, lobes[i], grid);
    auto hit = decoded<energy::LobeAlbedo>(cache, kLobeAlbedoEntries, cache.load(kLobeAlbedoEntries, keys[i]),
                                           [&](const json& j) { return lobeAlbedoFromCache(j, lobes[i]); });
    if (hit && hit->cells.size() == energy::gridCells(grid).size()) {
      out[i] = std::move(*hit);
      if (progress) progress->advance();
    } else {
      if (hit) cache.reject(kLobeAlbedoEntries);
      todo.push_back(lobes[i]);
      todoAt.push_back(i);
    }
  }
  if (todo.empty()) return out;
  std::vector<energy::LobeAlbedo> measured = energy::whiteFurnace(gpu, probes, todo, grid, progress);
  for (size_t k = 0; k < todo.size(); ++k) {
    const size_t i = todoAt[k];
    out[i] = std::move(measured[k]);
    out[i].lobe = &lobes[i];
    cache.store(kLobeAlbedoEntries, keys[i], cacheJson(out[i]));
  }
  return out;
}

}  // namespace mb::report
