// Compile benchmarks of issues 5 and 15 (docs/performance-compile.md explains the method):
//   a. throughput, permutations/s: in-process buildPermutations (-j1, -j2, no cache) with the
//      lean and the legacy driving of spirv-val / spirv-opt (same SPIR-V, checked), against one
//      glslangValidator -V + spirv-opt -O process pair per permutation on the same GLSL;
//   b. no-op rebuild with a warm cache: buildPermutations a second time (all hits), and the
//      whole `matbricks compile --scene` CLI run a second time;
//   c. cold compile time against scene size (1 .. 10000 distinct permutations), -j2;
//   d. GPU time of a specialized (folded) permutation against its feature-complete form, with
//      the features' inputs as constants and as run-time inputs (compiler/bench_engine/cost.hpp, as
//      `matbricks bench`), and the three SPIR-V instruction counts;
//   e. (--breakdown) where one permutation's time goes, stage by stage, on one thread;
//   f. (--recipes=FILE) spirv-opt recipes against RegisterPerformancePasses: time, instructions;
//   g. (--levels) the optimization levels -O0/-O1/-O2: compile time, where it goes, run time;
//   h. the levels' compile time on a scene of 60 distinct materials with IBL + directional +
//      point light at fp32 and fp16 (120 permutations), the shape the -O0 target is set on.
// Usage: mb_bench_compile REPEATS MAX_SIZE OUT_DIR SCENE [--breakdown] [--recipes=FILE] [--levels]
//        [--sections=LETTERS]  (writes OUT_DIR/compile.{json,md}).
// Medians of REPEATS runs (fewer for the largest sizes; the JSON records how many).
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <nlohmann/json.hpp>
#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>
#include <thread>
#include <tuple>
#include <type_traits>

#include "core/data_dir.hpp"
#include "bench_engine/bench_runner.hpp"
#include "bench_engine/cost.hpp"
#include "bench_engine/report.hpp"
#include "compile/build.hpp"
#include "compile/glsl_compiler.hpp"
#include "compile/target_checks.hpp"
#include "compile/targets.hpp"
#include "load/scene_desc.hpp"
#include "permute/scene_plan.hpp"
#include "write/package_contents.hpp"
#include "emit/bench_probe.hpp"
#include "permute/specialize.hpp"
#include "validate/probe_program.hpp"

using namespace mb;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using nlohmann::json;

namespace {

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

template <class F>
std::vector<double> timeRepeats(int repeats, F&& f) {
  std::vector<double> ms;
  for (int r = 0; r < repeats; ++r) {
    auto t0 = Clock::now();
    f();
    ms.push_back(msSince(t0));
  }
  return ms;
}

double peakRssMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // Linux: KiB
}

std::vector<MaterialDesc> exampleMaterials(const ShaderLibrary& lib) {
  std::vector<MaterialDesc> out;
  for (const auto& e : fs::directory_iterator(mb::compiledSourceDir() / "materials"))
    if (e.path().extension() == ".json") out.push_back(loadMaterialJson(e.path().string(), lib));
  std::sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.name < b.name; });
  return out;
}

const MaterialDesc& byName(const std::vector<MaterialDesc>& materials, const std::string& name) {
  for (const auto& m : materials)
    if (m.name == name) return m;
  throw std::runtime_error("no example material " + name);
}

// Whether a material's model shades these lights together in this environment.
bool shades(const ShaderLibrary& lib, const MaterialDesc& m, EnvironmentMode env,
            const std::vector<LightType>& lights) {
  const ShadingModel* model = lib.findModel(m.model);
  auto has = [](const auto& v, const auto& x) { return std::find(v.begin(), v.end(), x) != v.end(); };
  return has(model->environments, env) &&
         std::all_of(lights.begin(), lights.end(), [&](LightType l) { return has(model->lights, l); });
}

// A realistic list: every example material at one and at three light types, with no
// environment and with SH, where its model shades them.
std::vector<Permutation> throughputList(const ShaderLibrary& lib, const std::vector<MaterialDesc>& materials) {
  std::vector<Permutation> perms;
  for (const auto& m : materials) {
    for (std::vector<LightType> lights :
         {std::vector<LightType>{LightType::Dir}, {LightType::Dir, LightType::Point, LightType::Spot}})
      for (EnvironmentMode env : {EnvironmentMode::None, EnvironmentMode::Sh}) {
        if (!shades(lib, m, env, lights)) continue;
        Permutation p;
        p.material = &m;
        p.lights = lights;
        p.environment = env;
        perms.push_back(p);
      }
  }
  return perms;
}

BuildOptions options(unsigned jobs, fs::path cacheDir = {}) {
  BuildOptions o;
  o.jobs = jobs;
  o.cacheDir = std::move(cacheDir);
  return o;
}

// Writes each permutation's emitted GLSL (as the build emits it) and times
// glslangValidator -V + spirv-opt -O per file, `jobs` pairs at a time (xargs -P).
double externalPairsMs(const ShaderLibrary& lib, const std::vector<Permutation>& perms, const fs::path& dir,
                       unsigned jobs) {
  fs::create_directories(dir);
  std::ofstream list(dir / "files.txt");
  for (const auto& p : perms) {
    EmittedShader s = emitPermutation(lib, p, false, EmitMode::Engine);
    fs::path src = dir / (s.key + ".comp");
    std::ofstream(src, std::ios::binary) << s.glsl;
    list << src.string() << "\n";
  }
  list.close();
  std::string cmd = "xargs -P " + std::to_string(jobs) +
                    " -I{} sh -c 'glslangValidator -V --target-env vulkan1.1 -o {}.spv {} >/dev/null" +
                    " && spirv-opt -O --target-env=vulkan1.1 {}.spv -o {}.opt.spv' < " + (dir / "files.txt").string();
  auto t0 = Clock::now();
  if (std::system(cmd.c_str()) != 0) throw std::runtime_error("external compile failed: " + cmd);
  return msSince(t0);
}

BuildOptions options(unsigned jobs, CompilePipeline pipeline, fs::path cacheDir = {}) {
  BuildOptions o = options(jobs, std::move(cacheDir));
  o.pipeline = pipeline;
  return o;
}

// a: the current pipeline (Lean) and the one before issue 15 (Legacy) in the same run, their
// repeats interleaved so that a change of load hits both; both must give identical SPIR-V.
json benchThroughput(const ShaderLibrary& lib, const std::vector<Permutation>& perms, int repeats,
                     const fs::path& tmp) {
  json out{{"permutations", perms.size()}};
  for (unsigned jobs : {1u, 2u}) {
    const std::string j = std::to_string(jobs);
    BuildStats stats;
    std::vector<double> lean, legacy;
    std::vector<BuiltPermutation> leanBuilt, legacyBuilt;
    for (int r = 0; r < repeats; ++r) {
      auto t0 = Clock::now();
      legacyBuilt = buildPermutations(lib, perms, options(jobs, CompilePipeline::Legacy), &stats);
      legacy.push_back(msSince(t0));
      t0 = Clock::now();
      leanBuilt = buildPermutations(lib, perms, options(jobs, CompilePipeline::Lean), &stats);
      lean.push_back(msSince(t0));
    }
    for (size_t i = 0; i < perms.size(); ++i)
      if (leanBuilt[i].artifacts.spirv != legacyBuilt[i].artifacts.spirv ||
          leanBuilt[i].artifacts.reflection != legacyBuilt[i].artifacts.reflection)
        throw std::runtime_error("the lean and legacy pipelines differ on " + perms[i].key());
    for (auto [name, ms] : {std::pair{"in_process_j", bench::median(lean)}, {"legacy_j", bench::median(legacy)}})
      out[name + j] = json{{"ms_median", ms},
                           {"permutations_per_s", perms.size() * 1000.0 / ms},
                           {"compiled", stats.compiled},
                           {"unique_spirv", stats.uniqueSpirv}};
    out["lean_over_legacy_j" + j] = bench::median(legacy) / bench::median(lean);
    double ext = bench::median(timeRepeats(repeats, [&] { externalPairsMs(lib, perms, tmp / ("ext" + j), jobs); }));
    out["process_pairs_j" + j] = json{{"ms_median", ext}, {"permutations_per_s", perms.size() * 1000.0 / ext}};
    out["speedup_j" + j] = ext / bench::median(lean);
  }
  return out;
}

json benchNoop(const ShaderLibrary& lib, const std::vector<Permutation>& perms, int repeats, const fs::path& tmp,
               const std::string& cli, const std::string& scene) {
  fs::path cache = tmp / "cache";
  BuildStats cold, warm;
  double coldMs = bench::median(timeRepeats(1, [&] { buildPermutations(lib, perms, options(2, cache), &cold); }));
  double warmMs = bench::median(timeRepeats(repeats, [&] { buildPermutations(lib, perms, options(2, cache), &warm); }));
  json out{{"permutations", perms.size()},
           {"cold_ms", coldMs},
           {"warm_ms_median", warmMs},
           {"warm_cache_hits", warm.cacheHits},
           {"warm_compiled", warm.compiled}};
  if (scene.empty()) return out;
  std::string cmd = cli + " compile --scene " + scene + " -q -j 2 --cache-dir " + (tmp / "cli-cache").string() +
                    " -o " + (tmp / "pkg").string();
  auto run = [&] {
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("CLI failed: " + cmd);
  };
  out["cli"] = json{{"command", "matbricks compile --scene " + scene + " -q -j 2 --cache-dir CACHE -o PKG"},
                    {"cold_ms", bench::median(timeRepeats(1, run))},
                    {"noop_ms_median", bench::median(timeRepeats(repeats, run))}};
  return out;
}

// N distinct materials: filament_plastic with roughness and base colour made constants that
// differ per material, so that no two emit the same GLSL (no dedup, no cache sharing).
json benchScaling(const ShaderLibrary& lib, const MaterialDesc& base, size_t maxSize, int repeats,
                  const fs::path& tmp) {
  json rows = json::array();
  for (size_t n = 1; n <= maxSize; n *= 10) {
    std::vector<MaterialDesc> mats(n, base);
    for (size_t i = 0; i < n; ++i) {
      mats[i].name = "m" + std::to_string(i);
      for (auto& p : mats[i].params) {
        double t = double(i) / double(maxSize);
        if (p.name == "roughness") p.value = {0.2 + 0.6 * t};
        if (p.name == "baseColor") p.value = {0.1 + 0.8 * t, 0.5, 0.25 + 0.5 * (1 - t)};
        if (p.name == "roughness" || p.name == "baseColor") p.constant = true;
      }
    }
    std::vector<Permutation> perms = permutationsFor(mats);
    // Largest sizes take minutes per run: fewer repeats, recorded below.
    int reps = n >= 10000 ? 1 : n >= 1000 ? std::min(repeats, 3) : repeats;
    BuildStats stats;
    std::vector<double> ms;
    for (int r = 0; r < reps; ++r) {
      fs::path cache = tmp / ("scale-" + std::to_string(n) + "-" + std::to_string(r));  // cold every run
      auto t0 = Clock::now();
      buildPermutations(lib, perms, options(2, cache), &stats);
      ms.push_back(msSince(t0));
      fs::remove_all(cache);
    }
    double m = bench::median(ms);
    rows.push_back({{"permutations", n},
                    {"repeats", reps},
                    {"ms_median", m},
                    {"ms_per_permutation", m / n},
                    {"compiled", stats.compiled},
                    {"unique_spirv", stats.uniqueSpirv},
                    {"peak_rss_mib", peakRssMiB()}});
    std::cerr << "  scaling: " << n << " permutations, " << m << " ms\n";
  }
  return rows;
}

json levelCompileTimes(const ShaderLibrary& lib, const std::vector<Permutation>& perms, int repeats);

// The scene the -O0 target is stated on: 60 distinct materials, each shaded by a directional
// and a point light under ibl_lut, at fp32 and fp16: 120 permutations. The shipped materials
// in turn, each copy's first scalar input made a constant that differs per copy (as section c
// does), so that no two emit the same GLSL.
std::vector<MaterialDesc> sixtyMaterials(const ShaderLibrary& lib, const std::vector<MaterialDesc>& shipped) {
  std::vector<const MaterialDesc*> bases;
  for (const auto& m : shipped)
    if (shades(lib, m, EnvironmentMode::IblLut, {LightType::Dir, LightType::Point})) bases.push_back(&m);
  std::vector<MaterialDesc> out;
  for (size_t i = 0; i < 60; ++i) {
    MaterialDesc m = *bases[i % bases.size()];
    m.name = "m" + std::to_string(i);
    for (auto& p : m.params)
      if (!p.constant && !p.user && p.type == ValueType::Float) {
        p.constant = true;
        p.value = {0.2 + 0.6 * double(i) / 60.0};
        break;
      }
    out.push_back(std::move(m));
  }
  return out;
}

json benchSceneShape(const ShaderLibrary& lib, const std::vector<MaterialDesc>& sixty, int repeats) {
  std::vector<Permutation> perms;
  for (Precision precision : allPrecisions())
    for (const auto& m : sixty) {
      Permutation p;
      p.material = &m;
      p.lights = {LightType::Dir, LightType::Point};
      p.environment = EnvironmentMode::IblLut;
      p.precision = precision;
      perms.push_back(p);
    }
  return json{{"permutations", perms.size()},
              {"materials", sixty.size()},
              {"repeats", repeats},
              {"compile", levelCompileTimes(lib, perms, repeats)}};
}

// One form's cost as bench measures it (compiler/bench_engine/bench_runner.hpp measurePermutationCost):
// calibrated iterations, median and 95 % interval of paired repeats or "below resolution",
// and the static cost of its bench kernel.
json costOf(harness::VulkanHarness& gpu, const ShaderLibrary& lib, const Permutation& perm,
            const bench::CostOptions& o) {
  ProbeProgram probe = buildPermutationProbe(lib, perm);
  bench::BenchCost c = bench::measurePermutationCost(gpu, lib, perm, probe, o);
  json j = bench::toJson(c.measured);
  j["key"] = perm.key();
  j["static_cost_fma"] = c.staticCost;
  j["spirv_instructions"] = spirvInstructionCount(probe.compiled.spirv);
  return j;
}

// full / specialized: the ratio of the medians, bounds from the intervals' ends (each 95 %,
// so the bounds hold with at least 90 %), significant when the intervals are disjoint.
json ratioOf(const json& full, const json& specialized) {
  if (!full["resolved"].get<bool>() || !specialized["resolved"].get<bool>())
    return json{{"resolved", false},
                {"static", full["static_cost_fma"].get<double>() / specialized["static_cost_fma"].get<double>()}};
  const auto f = full["ns_per_eval_ci"], sp = specialized["ns_per_eval_ci"];
  return json{{"resolved", true},
              {"median", full["ns_per_eval"].get<double>() / specialized["ns_per_eval"].get<double>()},
              {"low", f[0].get<double>() / sp[1].get<double>()},
              {"high", f[1].get<double>() / sp[0].get<double>()},
              {"significant", sp[1].get<double>() < f[0].get<double>() || f[1].get<double>() < sp[0].get<double>()},
              {"static", full["static_cost_fma"].get<double>() / specialized["static_cost_fma"].get<double>()}};
}

// The feature-complete form with every feature's inputs read at run time (sampled over their
// ranges), as an uber shader driven by uniforms would: nothing for the compiler to fold.
MaterialDesc withRuntimeFeatureInputs(MaterialDesc m, const ShaderLibrary& lib) {
  const ShadingModel& model = *lib.findModel(m.model);
  for (auto& p : m.params)
    for (const auto& in : model.inputs)
      if (in.name == p.name && !in.feature.empty()) {
        p.constant = false;
        p.range = in.range;
      }
  return m;
}

// d: a specialized (folded) permutation against two feature-complete forms: every feature on
// with the folded / absent features' inputs as constants at the scene's (neutral) values,
// which is what the pruned-equals-full test compares with and which spirv-opt can partly fold;
// and with those inputs read at run time, the uber shader a keyword-free engine would ship.
json benchRuntime(const ShaderLibrary& lib, const std::vector<MaterialDesc>& materials, int repeats) {
  harness::VulkanHarness gpu;
  bench::CostOptions o;
  o.repeats = std::max<uint32_t>(9, static_cast<uint32_t>(repeats));  // cost.hpp default: a 96 % interval
  struct Case {
    std::string material;
    std::vector<std::string> folded;
    MaterialUse use;
  };
  std::vector<Case> cases{{"filament_plastic", {}, {}},
                          {"clearcoat_metal", {"clearcoat"}, {{{"clearCoat", {0.0}}}, {}}},
                          {"satin_sheen", {"sheen"}, {{{"sheenColor", {0.0, 0.0, 0.0}}}, {}}}};
  json rows = json::array();
  for (const auto& c : cases) {
    const MaterialDesc& loaded = byName(materials, c.material);
    // featureComplete takes the specialized material: the folded feature is switched back on
    // at the use's value (docs/scenes.md "Folding").
    MaterialDesc pruned = foldFeatures(loaded, c.folded, lib);
    MaterialDesc fullConstant = featureComplete(pruned, c.use, lib);
    MaterialDesc fullRuntime = withRuntimeFeatureInputs(fullConstant, lib);
    Permutation p, fc, fr;
    p.material = &pruned;
    p.folded = c.folded;
    fc.material = &fullConstant;
    fr.material = &fullRuntime;
    json sp = costOf(gpu, lib, p, o), jc = costOf(gpu, lib, fc, o), jr = costOf(gpu, lib, fr, o);
    rows.push_back({{"material", c.material},
                    {"specialized", sp},
                    {"feature_complete_constant", jc},
                    {"feature_complete_runtime", jr},
                    {"ratio_constant_over_specialized", ratioOf(jc, sp)},
                    {"ratio_runtime_over_specialized", ratioOf(jr, sp)}});
    std::cerr << "  runtime: " << c.material << " done\n";
  }
  return json{{"device", gpu.deviceName()},
              {"iterations_per_record", "calibrated per form (each form's cost.iterations_per_record)"},
              {"repeats", o.repeats},
              {"cost_method", bench::kCostMethod},
              {"static_cost_method", bench::kStaticCostMethod},
              {"rows", rows}};
}

// e (opt-in, --breakdown): where one permutation's compile time goes. Every stage that
// buildPermutations and the package writer run, called one at a time on one thread for each
// permutation of the throughput list; per stage, the median over REPEATS of its total over
// the list, per permutation. The spirv-opt passes of RegisterPerformancePasses are also run
// one optimizer per pass (checked to give the same module as one optimizer running them all),
// which adds a parse-to-IR and write-back per pass: that overhead is measured on its own
// ("no pass") and is included in each pass's figure.
struct StageClock {
  std::vector<std::string> order;
  std::map<std::string, double> total;  // of the current repeat
  std::map<std::string, std::vector<double>> perRepeat;
  void add(const std::string& stage, double ms) {
    if (!perRepeat.count(stage) && !total.count(stage)) order.push_back(stage);
    total[stage] += ms;
  }
  template <class F>
  auto time(const std::string& stage, F&& f) {
    auto t0 = Clock::now();
    if constexpr (std::is_void_v<decltype(f())>) {
      f();
      add(stage, msSince(t0));
    } else {
      auto r = f();
      add(stage, msSince(t0));
      return r;
    }
  }
  void endRepeat() {
    for (auto& [k, v] : total) perRepeat[k].push_back(v);
    total.clear();
  }
  json rows(size_t perms) const {
    json out = json::array();
    for (const auto& k : order)
      out.push_back({{"stage", k},
                     {"ms_per_permutation", bench::median(perRepeat.at(k)) / double(perms)},
                     {"ms_total_all_repeats", perRepeat.at(k)}});
    return out;
  }
};

std::vector<uint32_t> runPasses(const std::vector<uint32_t>& in, const std::vector<std::string>& flags) {
  spvtools::Optimizer o(SPV_ENV_VULKAN_1_1);
  if (!o.RegisterPassesFromFlags(flags)) throw std::runtime_error("spirv-opt flags rejected");
  spvtools::OptimizerOptions oo;
  oo.set_run_validator(false);  // validated once by the caller
  std::vector<uint32_t> out;
  if (!o.Run(in.data(), in.size(), &out, oo)) throw std::runtime_error("spirv-opt failed");
  return out;
}

json benchBreakdown(const ShaderLibrary& lib, const std::vector<Permutation>& perms, int repeats, const fs::path& tmp,
                    const std::string& scene) {
  std::vector<std::string> passes;
  {
    spvtools::Optimizer o(SPV_ENV_VULKAN_1_1);
    o.RegisterPerformancePasses();
    for (const char* n : o.GetPassNames()) passes.push_back(n);
  }
  StageClock clock, passClock, legacyClock;
  bool passesMatch = true, passesSameCount = true;
  for (int r = 0; r < repeats; ++r) {
    const fs::path cacheDir = tmp / ("breakdown-cache-" + std::to_string(r));
    const ShaderCache cache(cacheDir);
    for (const auto& p : perms) {
      EmittedShader s = clock.time("emit GLSL", [&] { return emitPermutation(lib, p, false, EmitMode::Engine); });
      const CacheIdentity key = clock.time("cache key (XXH3 over GLSL, brick hashes, versions)", [&] {
        return ShaderCache::identity(buildCacheKey(lib, s, OptimizationLevel::O2, {Target::Spirv}),
                                     {s.glsl, "", "", ""});
      });
      CompileOptions lean;
      lean.optimization = p.precision == Precision::Fp32 ? OptimizationLevel::O2 : OptimizationLevel::O0;
      CompileResult c = compileComputeGlsl(s.glsl, s.fileName, lean);
      clock.add("glslang parse", c.stages.parseMs);
      clock.add("glslang link", c.stages.linkMs);
      clock.add("glslang GlslangToSpv", c.stages.codegenMs);
      clock.add("spirv-val of glslang's module (friendly names off)", c.stages.validateMs);
      clock.add("spirv-opt performance passes (no re-validation)", c.stages.optimizeMs);
      clock.add("spirv-val of spirv-opt's module (friendly names off)", c.stages.validateOptimizedMs);
      CompiledArtifacts a;
      a.spirv = c.spirv;
      a.reflection = clock.time("SPIRV-Cross reflection", [&] { return reflectSpirv(a.spirv); });
      clock.time("SPIR-V content hash (XXH64)", [&] { return contentHash(a.spirv.data(), a.spirv.size() * 4); });
      clock.time("cache store (serialize, write, rename)", [&] { return cache.store(key, a); });
      clock.time("cache load (read, check, parse)", [&] {
        CompiledArtifacts back;
        return cache.load(key, back);
      });

      // The legacy pipeline's stages, on the same GLSL (its SPIR-V must be the same).
      CompileOptions legacy = lean;
      legacy.pipeline = CompilePipeline::Legacy;
      CompileResult l = compileComputeGlsl(s.glsl, s.fileName, legacy);
      if (l.spirv != c.spirv) throw std::runtime_error("legacy and lean SPIR-V differ: " + s.key);
      legacyClock.add("glslang parse + link + GlslangToSpv", l.frontEndMs);
      legacyClock.add("spirv-val of glslang's module (friendly names on)", l.stages.validateMs);
      legacyClock.add("spirv-opt performance passes (re-validating the input, friendly names on)", l.stages.optimizeMs);
      legacyClock.add("spirv-val of spirv-opt's module (friendly names on)", l.stages.validateOptimizedMs);

      // Cross-compilation to each other target, and its check separately.
      for (Target target : allTargets()) {
        const std::string& t = targetName(target);
        const TargetInfo& info = targetInfo(target);
        if (target == Target::Spirv || (!info.float16 && p.precision != Precision::Fp32)) continue;
        std::string out =
            clock.time("SPIRV-Cross + check: " + t, [&] { return crossCompile(a.spirv, target, s.fileName); });
        if (info.language == TargetLanguage::Glsl)
          clock.time("  of which the check: " + t, [&] { return checkGlsl(out, info.es); });
        if (info.language == TargetLanguage::Hlsl)
          clock.time("  of which the check: " + t, [&] { return checkHlsl(out); });
      }

      // spirv-opt pass by pass, summed per pass name over its occurrences in the recipe.
      if (lean.optimization != OptimizationLevel::O0) {
        CompileOptions raw;
        raw.optimization = OptimizationLevel::O0;
        raw.validate = false;
        std::vector<uint32_t> m = compileComputeGlsl(s.glsl, s.fileName, raw).spirv;
        passClock.time("no pass (parse to IR, write back)", [&] { return runPasses(m, {}); });
        for (const auto& pass : passes) m = passClock.time(pass, [&] { return runPasses(m, {"--" + pass}); });
        passesMatch = passesMatch && m == c.spirv;
        passesSameCount = passesSameCount && spirvInstructionCount(m) == spirvInstructionCount(c.spirv);
      }
    }
    fs::remove_all(cacheDir);
    clock.endRepeat();
    passClock.endRepeat();
    legacyClock.endRepeat();
  }
  json out{{"permutations", perms.size()},
           {"repeats", repeats},
           {"stages", clock.rows(perms.size())},
           {"legacy_stages", legacyClock.rows(perms.size())},
           {"spirv_opt_passes", passClock.rows(perms.size())},
           {"spirv_opt_recipe", passes},
           {"pass_by_pass_equals_one_optimizer", passesMatch},
           {"pass_by_pass_same_instruction_count", passesSameCount}};

  // Package writing, for the scene (its own permutations), -j1 without a cache.
  if (!scene.empty()) {
    SceneDesc desc = loadScene(scene, lib);
    ScenePlan plan = planScene(desc, lib);
    std::vector<double> buildMs, writeMs;
    for (int r = 0; r < repeats; ++r) {
      auto t0 = Clock::now();
      BuildOptions o = options(1);
      o.targets = desc.targets;
      std::vector<BuiltPermutation> built = buildPermutations(lib, plan.required, o);
      buildMs.push_back(msSince(t0));
      t0 = Clock::now();
      PackageWriter pkg;
      PackageInputs in;
      in.lib = &lib;
      in.plan = &plan;
      in.built = &built;
      in.targets = desc.targets;
      in.sceneFile = scene;
      addPackageFiles(pkg, in);
      pkg.commit(tmp / "breakdown-pkg");
      writeMs.push_back(msSince(t0));
    }
    const double n = double(plan.required.size());
    out["package"] = {{"scene", scene},
                      {"permutations", plan.required.size()},
                      {"targets", targetNames(desc.targets)},
                      {"build_j1_ms_per_permutation", bench::median(buildMs) / n},
                      {"write_package_ms_per_permutation", bench::median(writeMs) / n}};
  }
  return out;
}

std::string fmt(double v, int digits = 3) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

// A ratioOf() result as a table cell.
std::string ratioText(const json& q) {
  if (!q["resolved"].get<bool>()) return std::string("n/a (below resolution)");
  return fmt(q["median"]) + "x (" + fmt(q["low"]) + " to " + fmt(q["high"]) + ")" +
         (q["significant"].get<bool>() ? ", significant" : ", not significant");
}

// f (opt-in, --recipes=FILE): spirv-opt recipes against RegisterPerformancePasses on the
// glslang output of every permutation of the list: optimizer time (one thread, median over
// REPEATS of the total) and SPIR-V instruction counts. FILE: one recipe per line,
// "name: --pass --pass ...".
json benchRecipes(const ShaderLibrary& lib, const std::vector<Permutation>& perms, int repeats,
                  const std::string& file) {
  std::vector<std::pair<std::string, std::vector<std::string>>> recipes{{"performance", {"-O"}}};
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line.substr(line.find(':') + 1));
    std::vector<std::string> flags;
    for (std::string w; words >> w;) flags.push_back(w);
    recipes.push_back({line.substr(0, line.find(':')), flags});
  }
  std::vector<std::vector<uint32_t>> inputs;
  for (const auto& p : perms) {
    EmittedShader s = emitPermutation(lib, p, false, EmitMode::Engine);
    CompileOptions raw;
    raw.optimization = OptimizationLevel::O0;
    inputs.push_back(compileComputeGlsl(s.glsl, s.fileName, raw).spirv);
  }
  // Repeats interleaved across the recipes, so that a change of load hits all of them.
  std::vector<std::vector<double>> ms(recipes.size());
  std::vector<std::vector<size_t>> counts(recipes.size());
  for (int r = 0; r < repeats; ++r)
    for (size_t k = 0; k < recipes.size(); ++k) {
      counts[k].clear();
      auto t0 = Clock::now();
      for (const auto& m : inputs) counts[k].push_back(spirvInstructionCount(runPasses(m, recipes[k].second)));
      ms[k].push_back(msSince(t0));
    }
  const std::vector<size_t>& reference = counts[0];
  json rows = json::array();
  for (size_t k = 0; k < recipes.size(); ++k) {
    const auto& [name, flags] = recipes[k];
    size_t total = 0, more = 0, fewer = 0;
    long worst = 0;
    for (size_t i = 0; i < counts[k].size(); ++i) {
      total += counts[k][i];
      more += counts[k][i] > reference[i];
      fewer += counts[k][i] < reference[i];
      worst = std::max(worst, long(counts[k][i]) - long(reference[i]));
    }
    spvtools::Optimizer registered(SPV_ENV_VULKAN_1_1);
    registered.RegisterPassesFromFlags(flags);
    const double perPermutation = bench::median(ms[k]) / double(inputs.size());
    rows.push_back({{"recipe", name},
                    {"flags", flags},
                    {"passes", registered.GetPassNames().size()},
                    {"optimizer_ms_per_permutation", perPermutation},
                    {"optimizer_ms_all_repeats", ms[k]},
                    {"instructions_total", total},
                    {"permutations_with_more_instructions", more},
                    {"permutations_with_fewer_instructions", fewer},
                    {"largest_increase", worst}});
    std::cerr << "  " << name << ": " << perPermutation << " ms, " << total << " instructions, " << more << " more, "
              << fewer << " fewer, worst +" << worst << "\n";
  }
  return rows;
}

// g (opt-in, --levels): the optimization levels (`compile -O`, docs/performance-compile.md
// "Levels") on the throughput list, repeats interleaved across levels so that a change of load
// hits all three: cold builds without a cache at -j1 and -j2 with the package's settings (kernel
// and fragment shader, SPIR-V), and at -j2 with one stage (`compile --stages fragment`, then
// `kernel`); the kernels' compile stages on one thread (glslang, spirv-val, spirv-opt), which
// says where the remaining time goes; SPIR-V instructions; and the run-time cost of three
// materials' bench kernels compiled at each level, as `bench -O` measures it.
// Each level's compile time per permutation (-j1, -j2, -j2 with one stage) and where a
// kernel's time goes on one thread, medians of `repeats` runs interleaved across levels.
json levelCompileTimes(const ShaderLibrary& lib, const std::vector<Permutation>& perms, int repeats) {
  const OptimizationLevel levels[] = {OptimizationLevel::O0, OptimizationLevel::O1, OptimizationLevel::O2};
  std::vector<EmittedShader> kernels;
  for (const auto& p : perms) kernels.push_back(emitPermutation(lib, p, false, EmitMode::Engine));
  std::map<std::string, std::map<std::string, std::vector<double>>> ms;  // level -> measure -> repeats
  std::map<std::string, size_t> instructions;
  for (int r = 0; r < repeats; ++r)
    for (OptimizationLevel level : levels) {
      const std::string name = optimizationLevelName(level);
      for (unsigned jobs : {1u, 2u}) {
        BuildOptions o = options(jobs);
        o.optimization = level;
        const auto t0 = Clock::now();
        const std::vector<BuiltPermutation> built = buildPermutations(lib, perms, o);
        ms[name]["build_j" + std::to_string(jobs)].push_back(msSince(t0));
        size_t total = 0;
        for (const auto& b : built) total += b.spirvInstructions;
        instructions[name] = total;
      }
      for (const PackageStages stages : {PackageStages{false, true}, PackageStages{true, false}}) {
        BuildOptions o = options(2);
        o.optimization = level;
        o.stages = stages;
        const auto t0 = Clock::now();
        buildPermutations(lib, perms, o);
        ms[name][stages.kernel ? "build_j2_kernel_only" : "build_j2_fragment_only"].push_back(msSince(t0));
      }
      CompileStageTimes sum;
      for (size_t i = 0; i < kernels.size(); ++i) {
        // fp16 kernels are never optimized (docs/fp16.md), as a package builds them.
        CompileOptions co;
        co.optimization = perms[i].precision == Precision::Fp16 ? OptimizationLevel::O0 : level;
        const CompileStageTimes t = compileComputeGlsl(kernels[i].glsl, kernels[i].fileName, co).stages;
        sum.parseMs += t.parseMs + t.linkMs + t.codegenMs;
        sum.validateMs += t.validateMs + t.validateOptimizedMs;
        sum.optimizeMs += t.optimizeMs;
      }
      ms[name]["kernel_glslang"].push_back(sum.parseMs);
      ms[name]["kernel_spirv_val"].push_back(sum.validateMs);
      ms[name]["kernel_spirv_opt"].push_back(sum.optimizeMs);
    }
  json compile = json::array();
  for (OptimizationLevel level : levels) {
    const std::string name = optimizationLevelName(level);
    json row{{"level", name}, {"spirv_instructions_total", instructions[name]}};
    for (const auto& [measure, values] : ms[name]) {
      const double perPermutation = bench::median(values) / double(perms.size());
      row[measure + "_ms_per_permutation"] = perPermutation;
      if (measure.rfind("build_", 0) == 0) row[measure + "_permutations_per_s"] = 1000.0 / perPermutation;
    }
    compile.push_back(row);
    std::cerr << "  " << name << ": -j2 " << row["build_j2_permutations_per_s"].get<double>() << " permutations/s\n";
  }
  return compile;
}

json benchLevels(const ShaderLibrary& lib, const std::vector<MaterialDesc>& materials,
                 const std::vector<Permutation>& perms, int repeats) {
  const OptimizationLevel levels[] = {OptimizationLevel::O0, OptimizationLevel::O1, OptimizationLevel::O2};
  const json compile = levelCompileTimes(lib, perms, repeats);

  harness::VulkanHarness gpu;
  bench::CostOptions o;
  o.repeats = std::max<uint32_t>(9, static_cast<uint32_t>(repeats));
  json runtime = json::array();
  for (const std::string material : {"filament_plastic", "clearcoat_metal", "satin_sheen"}) {
    Permutation p;
    p.material = &byName(materials, material);
    std::map<std::string, json> byLevel;
    for (OptimizationLevel level : levels) {
      o.optimization = level;
      byLevel[optimizationLevelName(level)] = costOf(gpu, lib, p, o);
    }
    runtime.push_back({{"material", material},
                       {"O0", byLevel["O0"]},
                       {"O1", byLevel["O1"]},
                       {"O2", byLevel["O2"]},
                       {"ratio_O0_over_O2", ratioOf(byLevel["O0"], byLevel["O2"])},
                       {"ratio_O1_over_O2", ratioOf(byLevel["O1"], byLevel["O2"])}});
    std::cerr << "  levels run time: " << material << " done\n";
  }
  return json{{"permutations", perms.size()},
              {"repeats", repeats},
              {"o1_passes", o1PassFlags()},
              {"compile", compile},
              {"device", gpu.deviceName()},
              {"runtime_repeats", o.repeats},
              {"runtime", runtime}};
}

// The levels' compile table of sections g and h.
std::string markdownLevelCompile(const json& compile) {
  std::string s =
      "| level | perm/s -j1 | perm/s -j2 | perm/s -j2 fragment only | perm/s -j2 kernel only | ms/perm "
      "-j2 | kernel glslang ms | kernel spirv-val ms | kernel spirv-opt ms | SPIR-V instructions "
      "|\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& row : compile)
    s += "| " + row["level"].get<std::string>() + " | " + fmt(row["build_j1_permutations_per_s"]) + " | " +
         fmt(row["build_j2_permutations_per_s"]) + " | " + fmt(row["build_j2_fragment_only_permutations_per_s"]) +
         " | " + fmt(row["build_j2_kernel_only_permutations_per_s"]) + " | " + fmt(row["build_j2_ms_per_permutation"]) +
         " | " + fmt(row["kernel_glslang_ms_per_permutation"]) + " | " +
         fmt(row["kernel_spirv_val_ms_per_permutation"]) + " | " + fmt(row["kernel_spirv_opt_ms_per_permutation"]) +
         " | " + std::to_string(row["spirv_instructions_total"].get<size_t>()) + " |\n";
  return s;
}

std::string markdownSceneShape(const json& h) {
  return "## h. Optimization levels on " + std::to_string(h["materials"].get<size_t>()) + " materials, " +
         std::to_string(h["permutations"].get<size_t>()) +
         " permutations (directional + point + ibl_lut, fp32 and fp16; SPIR-V with fragment shaders, no cache, "
         "median of " +
         std::to_string(h["repeats"].get<int>()) + " repeats interleaved across levels)\n\n" +
         markdownLevelCompile(h["compile"]);
}

std::string markdownLevels(const json& g) {
  std::string s = "## g. Optimization levels (" + std::to_string(g["permutations"].get<size_t>()) +
                  " permutations, SPIR-V with fragment shaders, no cache, median of " +
                  std::to_string(g["repeats"].get<int>()) + " repeats interleaved across levels)\n\n" +
                  markdownLevelCompile(g["compile"]);
  s += "\nRun time of the bench kernel compiled at each level on " + g["device"].get<std::string>() +
       " (cost per evaluation, median of " + std::to_string(g["runtime_repeats"].get<int>()) +
       " paired repeats with its 95 % interval; ratio to O2 with bounds from the intervals' ends):\n\n"
       "| material | O0 | O1 | O2 | O0 / O2 | O1 / O2 |\n|---|---|---|---|---|---|\n";
  for (const auto& row : g["runtime"])
    s += "| " + row["material"].get<std::string>() + " | " + row["O0"]["text"].get<std::string>() + " | " +
         row["O1"]["text"].get<std::string>() + " | " + row["O2"]["text"].get<std::string>() + " | " +
         ratioText(row["ratio_O0_over_O2"]) + " | " + ratioText(row["ratio_O1_over_O2"]) + " |\n";
  return s;
}

std::string markdownBreakdown(const json& b) {
  std::string s = "## e. Where the time goes, one thread (" + std::to_string(b["permutations"].get<size_t>()) +
                  " permutations, median of " + std::to_string(b["repeats"].get<int>()) +
                  " repeats)\n\nms per permutation, each stage run on its own.\n\n| stage | ms |\n|---|---|\n";
  for (const auto& row : b["stages"])
    s += "| " + row["stage"].get<std::string>() + " | " + fmt(row["ms_per_permutation"]) + " |\n";
  s += "\nThe legacy pipeline (before issue 15) on the same GLSL and SPIR-V:\n\n| stage | ms |\n|---|---|\n";
  for (const auto& row : b["legacy_stages"])
    s += "| " + row["stage"].get<std::string>() + " | " + fmt(row["ms_per_permutation"]) + " |\n";
  s += "\nspirv-opt pass by pass (one optimizer per pass, each including a parse to IR and write-back; "
       "summed over a pass's occurrences in the recipe; the same module as one optimizer running them all: " +
       std::string(b["pass_by_pass_equals_one_optimizer"].get<bool>() ? "yes" : "no") +
       ", the same instruction count: " +
       std::string(b["pass_by_pass_same_instruction_count"].get<bool>() ? "yes" : "no") +
       "):\n\n| pass | ms |\n|---|---|\n";
  for (const auto& row : b["spirv_opt_passes"])
    s += "| " + row["stage"].get<std::string>() + " | " + fmt(row["ms_per_permutation"]) + " |\n";
  if (b.contains("package")) {
    const json& p = b["package"];
    std::string targets;
    for (const auto& t : p["targets"]) targets += (targets.empty() ? "" : ",") + t.get<std::string>();
    s += "\nPackage of " + p["scene"].get<std::string>() + " (" + std::to_string(p["permutations"].get<size_t>()) +
         " permutations, targets " + targets + "): buildPermutations -j1 " + fmt(p["build_j1_ms_per_permutation"]) +
         " ms per permutation, addPackageFiles + commit " + fmt(p["write_package_ms_per_permutation"]) +
         " ms per permutation.\n";
  }
  return s;
}

std::string markdown(const json& r) {
  std::string s = "# Compile benchmarks\n\n" + r["command"].get<std::string>() +
                  "\n\nMachine: " + r["machine"].get<std::string>() + "\n\n";
  if (r.contains("throughput")) {
    const json& t = r["throughput"];
    s += "## a. Throughput (" + std::to_string(t["permutations"].get<size_t>()) +
         " permutations, SPIR-V, optimized and validated, no cache)\n\n"
         "Legacy: the pipeline before issue 15 (friendly names in spirv-val, spirv-opt re-validating its input), "
         "measured in the same run, repeats interleaved; its SPIR-V is identical.\n\n"
         "| jobs | in-process perm/s | legacy perm/s | lean / legacy | process pairs perm/s | in-process / pairs |\n"
         "|---|---|---|---|---|---|\n";
    for (int j : {1, 2}) {
      std::string k = std::to_string(j);
      s += "| " + k + " | " + fmt(t["in_process_j" + k]["permutations_per_s"]) + " | " +
           fmt(t["legacy_j" + k]["permutations_per_s"]) + " | " + fmt(t["lean_over_legacy_j" + k]) + " | " +
           fmt(t["process_pairs_j" + k]["permutations_per_s"]) + " | " + fmt(t["speedup_j" + k]) + " |\n";
    }
  }
  if (r.contains("noop")) {
    const json& n = r["noop"];
    s += "\n## b. No-op rebuild, warm cache\n\n| what | cold ms | warm ms |\n|---|---|---|\n| buildPermutations, " +
         std::to_string(n["permutations"].get<size_t>()) + " permutations, -j2 | " + fmt(n["cold_ms"]) + " | " +
         fmt(n["warm_ms_median"]) + " |\n";
    if (n.contains("cli"))
      s += "| `" + n["cli"]["command"].get<std::string>() + "` | " + fmt(n["cli"]["cold_ms"]) + " | " +
           fmt(n["cli"]["noop_ms_median"]) + " |\n";
  }
  if (r.contains("scaling")) {
    s +=
        "\n## c. Cold compile time against scene size (-j2)\n\n| permutations | repeats | ms | ms per permutation | peak RSS MiB |\n|---|---|---|---|---|\n";
    for (const auto& row : r["scaling"])
      s += "| " + std::to_string(row["permutations"].get<size_t>()) + " | " +
           std::to_string(row["repeats"].get<int>()) + " | " + fmt(row["ms_median"], 5) + " | " +
           fmt(row["ms_per_permutation"]) + " | " + fmt(row["peak_rss_mib"]) + " |\n";
  }
  if (r.contains("runtime")) {
    s += "\n## d. Specialized against feature-complete, on " + r["runtime"]["device"].get<std::string>() +
         "\n\nCost per evaluation (median of " + std::to_string(r["runtime"]["repeats"].get<int>()) +
         " paired repeats, 95 % interval; iterations calibrated per form), the ratio to specialized (bounds from the "
         "intervals' ends; \"significant\": disjoint intervals), the static cost (fp32 FMA slots) and its ratio, "
         "and SPIR-V instructions after spirv-opt. Full (constants): every feature on, the folded or absent "
         "features' inputs compile-time constants at the scene's values. Full (run-time): the same inputs read from "
         "the record, as a uniform-driven uber shader.\n\n"
         "| material | form | cost / eval (95 % interval) | ratio to specialized | static cost | static ratio | "
         "SPIR-V instr. |\n|---|---|---|---|---:|---:|---:|\n";
    for (const auto& row : r["runtime"]["rows"])
      for (const auto& [key, label, ratio] :
           {std::tuple{"specialized", "specialized", ""},
            {"feature_complete_constant", "full (constants)", "ratio_constant_over_specialized"},
            {"feature_complete_runtime", "full (run-time)", "ratio_runtime_over_specialized"}}) {
        const json& f = row[key];
        s += "| " + row["material"].get<std::string>() + " | " + label + " | " + f["text"].get<std::string>() + " | " +
             (*ratio ? ratioText(row[ratio]) : std::string("1")) + " | " + fmt(f["static_cost_fma"]) + " | " +
             (*ratio ? fmt(row[ratio]["static"]) + "x" : std::string("1")) + " | " +
             std::to_string(f["spirv_instructions"].get<size_t>()) + " |\n";
      }
  }
  if (r.contains("breakdown")) s += "\n" + markdownBreakdown(r["breakdown"]);
  if (r.contains("levels")) s += "\n" + markdownLevels(r["levels"]);
  if (r.contains("scene_shape")) s += "\n" + markdownSceneShape(r["scene_shape"]);
  if (r.contains("recipes")) {
    s += "\n## f. spirv-opt recipes against RegisterPerformancePasses (one thread, median)\n\n"
         "| recipe | passes | spirv-opt ms per permutation | instructions, all permutations | permutations with more | "
         "with fewer | largest increase |\n|---|---|---|---|---|---|---|\n";
    for (const auto& row : r["recipes"])
      s += "| " + row["recipe"].get<std::string>() + " | " + std::to_string(row["passes"].get<size_t>()) + " | " +
           fmt(row["optimizer_ms_per_permutation"]) + " | " + std::to_string(row["instructions_total"].get<size_t>()) +
           " | " + std::to_string(row["permutations_with_more_instructions"].get<size_t>()) + " | " +
           std::to_string(row["permutations_with_fewer_instructions"].get<size_t>()) + " | " +
           std::to_string(row["largest_increase"].get<long>()) + " |\n";
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = argc > 1 ? std::atoi(argv[1]) : 5;
  size_t maxSize = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 10000;
  fs::path outDir = argc > 3 ? argv[3] : "bench/results";
  std::string scene = argc > 4 ? argv[4] : "";
  // Options after the four positional arguments: --breakdown adds section e; --sections=LETTERS
  // runs only those sections (default abcd, plus e with --breakdown).
  std::string sections = "abcd";
  std::string extra, recipesFile;
  for (int i = 5; i < argc; ++i) {
    const std::string a = argv[i];
    extra += " " + a;
    if (a == "--breakdown")
      sections += "e";
    else if (a == "--levels")
      sections += "g";
    else if (a.rfind("--recipes=", 0) == 0)
      sections += "f", recipesFile = a.substr(10);
    else if (a.rfind("--sections=", 0) == 0)
      sections = a.substr(11);
    else {
      std::cerr << "mb_bench_compile: unknown option " << a << "\n";
      return 2;
    }
  }
  auto want = [&](char c) { return sections.find(c) != std::string::npos; };
  std::string cli = (fs::absolute(argv[0]).parent_path() / "matbricks").string();
  try {
    ShaderLibrary lib = ShaderLibrary::load(ShaderLibrary::defaultRoot());
    std::vector<MaterialDesc> materials = exampleMaterials(lib);
    fs::path tmp = fs::temp_directory_path() / ("mb_bench_compile_" + std::to_string(::getpid()));
    fs::create_directories(tmp);
    // glslang's one-time process initialization, paid before anything is timed.
    compileComputeGlsl(emitPermutation(lib, permutationsFor(materials).front()).glsl, "warmup.glsl");
    std::vector<Permutation> perms = throughputList(lib, materials);
    json r;
    r["command"] = "mb_bench_compile " + std::to_string(repeats) + " " + std::to_string(maxSize) + " " +
                   outDir.string() + " " + scene + extra;
    r["machine"] = std::to_string(std::thread::hardware_concurrency()) + " hardware threads";
    r["toolchain"] = toolchainVersion();
    if (want('e')) {
      // First, so that the targets' one-time glslang initializations (per #version) are paid
      // by a warm-up pass here and not in a timed repeat.
      std::cerr << "e. breakdown\n";
      benchBreakdown(lib, {perms.front()}, 1, tmp, "");
      r["breakdown"] = benchBreakdown(lib, perms, repeats, tmp, scene);
    }
    if (want('f')) {
      std::cerr << "f. recipes\n";
      r["recipes"] = benchRecipes(lib, perms, repeats, recipesFile);
    }
    if (want('a')) {
      std::cerr << "a. throughput\n";
      r["throughput"] = benchThroughput(lib, perms, repeats, tmp);
    }
    if (want('b')) {
      std::cerr << "b. no-op rebuild\n";
      r["noop"] = benchNoop(lib, perms, repeats, tmp, cli, scene);
    }
    if (want('c')) {
      std::cerr << "c. scaling\n";
      r["scaling"] = benchScaling(lib, byName(materials, "filament_plastic"), maxSize, repeats, tmp);
    }
    if (want('d')) {
      std::cerr << "d. run time\n";
      r["runtime"] = benchRuntime(lib, materials, repeats);
    }
    if (want('g')) {
      std::cerr << "g. optimization levels\n";
      r["levels"] = benchLevels(lib, materials, perms, repeats);
    }
    if (want('h')) {
      std::cerr << "h. optimization levels on 60 materials, 120 permutations\n";
      const std::vector<MaterialDesc> sixty = sixtyMaterials(lib, materials);
      r["scene_shape"] = benchSceneShape(lib, sixty, repeats);
    }
    fs::remove_all(tmp);
    fs::create_directories(outDir);
    std::ofstream(outDir / "compile.json") << r.dump(2) << "\n";
    std::ofstream(outDir / "compile.md") << markdown(r);
    std::cout << markdown(r);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "mb_bench_compile: " << e.what() << "\n";
    return 1;
  }
}
