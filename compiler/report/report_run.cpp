#include "report/report_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "emit/bench_probe.hpp"
#include "energy/brick_sweep.hpp"
#include "energy/lobes.hpp"
#include "report/result_memo.hpp"

namespace mb::report {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

void addUnique(std::vector<std::string>& to, const std::vector<std::string>& from) {
  for (const auto& s : from)
    if (std::find(to.begin(), to.end(), s) == to.end()) to.push_back(s);
}

MaterialSection measureMaterial(const ShaderLibrary& lib, harness::VulkanHarness& gpu, const MaterialPermutations& mp,
                                const ReportOptions& o, ResultCache& cache, ProgressSink* progress) {
  const MaterialDesc& m = *mp.material;
  MaterialSection s{m.name, m.model, m.sourceFile, mp.notes, {}, {}};
  if (o.previews)
    s.previews = o.previews(m, gpu);
  else
    s.previews.text = "No previews: not asked for (--no-previews).";
  if (progress) progress->advance();
  for (const auto& perm : mp.permutations) {
    ProbeProgram probe = buildPermutationProbe(lib, perm);
    PermutationRow row;
    row.validation = validateProbe(gpu, probe, "permutation", o.samples, o.seed);
    row.bricks = probe.shader.bricks;
    bench::BenchCost cost = cachedPermutationCost(cache, gpu, lib, perm, probe, o.cost);
    row.cost = cost.measured;
    row.staticCost = cost.staticCost;
    if (progress) progress->advance();
    s.permutations.push_back(std::move(row));
  }
  return s;
}

// The slots whose bricks the reported shaders call, in the library's slot order.
std::vector<std::string> slotsOf(const ShaderLibrary& lib, const std::vector<std::string>& bricks) {
  std::vector<std::string> out;
  for (const auto& slot : lib.slots())
    if (std::any_of(bricks.begin(), bricks.end(), [&](const std::string& id) {
          const Brick* b = lib.findBrick(id);
          return b && b->slot == slot.name;
        }))
      out.push_back(slot.name);
  return out;
}

}  // namespace

bench::CostOptions ReportOptions::quickCost() {
  bench::CostOptions c;
  c.repeats = 6;  // the fewest paired repeats that give a 95 % interval (bench_engine/cost_interval.hpp)
  c.targetDispatchMs = 2;
  return c;
}

energy::EnergyGrid ReportOptions::reportGrid() {
  energy::EnergyGrid g = energy::EnergyGrid::fine();
  g.perceptualRoughness = {0.045, 0.25, 0.5, 0.75, 1.0};
  g.resolution = energy::EnergyGrid::coarse().resolution;
  return g;
}

std::vector<energy::Lobe> lobesUsing(const std::vector<energy::Lobe>& all, const std::vector<std::string>& bricks) {
  std::vector<energy::Lobe> out;
  for (const auto& lobe : all)
    if (std::all_of(lobe.factors.begin(), lobe.factors.end(),
                    [&](const Brick* b) { return std::find(bricks.begin(), bricks.end(), b->id) != bricks.end(); }))
      out.push_back(lobe);
  return out;
}

ReportData runReport(const ShaderLibrary& lib, harness::VulkanHarness& gpu,
                     const std::vector<MaterialPermutations>& materials, const ReportOptions& o,
                     ProgressSink* progress) {
  ReportData r;
  r.device = gpu.deviceName();
  r.toolchain = toolchainVersion();
  std::vector<std::string> usedBricks;
  ResultCache cache(o.resultCacheDir);

  auto t0 = Clock::now();
  for (const auto& mp : materials) {
    r.materials.push_back(measureMaterial(lib, gpu, mp, o, cache, progress));
    for (const auto& row : r.materials.back().permutations) addUnique(usedBricks, row.bricks);
  }
  r.times.push_back({"materials (validate + bench kernels)", secondsSince(t0)});

  if (o.slots) {
    t0 = Clock::now();
    bench::BenchOptions bo;
    bo.slots = o.slotFilter.empty() ? slotsOf(lib, usedBricks) : o.slotFilter;
    bo.samples = o.slotSamples;
    bo.seed = o.seed;
    bo.cost = o.cost;
    // An empty slot list means "every slot" to bench; here it means there is nothing to chart.
    const bench::BrickItemMemo memo = brickItemMemo(cache, gpu, lib, bo);
    if (!bo.slots.empty()) r.slots = bench::runBench(lib, gpu, {}, bo, progress, &memo);
    r.times.push_back({"slots (bench)", secondsSince(t0)});
  }

  if (o.energy) {
    t0 = Clock::now();
    r.energy = std::make_unique<EnergySection>();
    r.energy->grid = o.grid;
    r.energy->lobes = lobesUsing(energy::energyLobes(lib), usedBricks);
    energy::ProbeCache probes(lib);
    if (!r.energy->lobes.empty())
      r.energy->furnace = cachedWhiteFurnace(cache, gpu, probes, r.energy->lobes, o.grid, progress);
    r.times.push_back({"energy (white furnace)", secondsSince(t0)});
  }

  if (o.lightMethods) {
    t0 = Clock::now();
    // The first material that is reported with area lights, for the area lights it has.
    for (const auto& mp : materials) {
      std::vector<LightType> shapes;
      for (const auto& p : mp.permutations)
        for (LightType t : bench::areaLightsOf(p.lights))
          if (std::find(shapes.begin(), shapes.end(), t) == shapes.end()) shapes.push_back(t);
      if (shapes.empty() || !bench::hasLightMethods(lib, *mp.material)) continue;
      bench::LightMethodOptions lo;
      lo.lights = o.lightMethodLights;
      lo.seed = o.seed;
      lo.cost = o.cost;
      r.lightMethods =
          LightMethodsSection{mp.material->name, bench::measureLightMethods(gpu, lib, *mp.material, lo, shapes),
                              static_cast<int>(o.cost.repeats)};
      r.times.push_back({"area light methods (bench kernels + brute force)", secondsSince(t0)});
      break;
    }
  }

  if (o.lut) {
    t0 = Clock::now();
    LutSection l;
    l.generated = lut::generateDfgLutOnGpu(gpu, lib, o.lutSize, 0);
    l.check = lut::checkLut(lib, l.generated.table, o.lutCheckGrid, true, progress);
    r.lut = std::move(l);
    r.times.push_back({"DFG LUT (GPU + check)", secondsSince(t0)});
  }
  if (cache.enabled()) {
    r.resultCacheDir = o.resultCacheDir.string();
    for (const auto& [kind, what] : {std::pair{kPermutationCostEntries, "permutation costs"},
                                     std::pair{kBrickItemEntries, "slot chart bricks (cost and error)"},
                                     std::pair{kLobeAlbedoEntries, "lobe albedos"}}) {
      const ResultCache::Counts c = cache.counts(kind);
      r.cacheUse.push_back({what, c.hits, c.hits + c.misses, c.rejected});
    }
  }
  return r;
}

std::vector<std::string> ReportData::failures() const {
  std::vector<std::string> f;
  for (const auto& m : materials) {
    if (m.previews.failed) f.push_back(m.name + ": preview outside the tolerance of the reference render");
    for (const auto& p : m.permutations)
      if (!p.validation.passed()) f.push_back(p.validation.key + ": outside its tolerance");
  }
  if (energy)
    for (const auto& a : energy->furnace)
      if (!a.gpuMatchesReference())
        f.push_back(a.lobe->name + ": GPU albedo differs from the reference beyond the derived bound");
  if (lut && !lut->check.passed()) f.push_back("DFG LUT outside its promised accuracy");
  if (layerMessages) f.push_back("Vulkan validation layer messages");
  return f;
}

}  // namespace mb::report
