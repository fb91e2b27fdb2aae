// Compile benchmarks of issue 5 item 7 (docs/performance-compile.md explains the method):
//   a. throughput, permutations/s: in-process buildPermutations (-j1, -j2, no cache) against
//      one glslangValidator -V + spirv-opt -O process pair per permutation on the same GLSL;
//   b. no-op rebuild with a warm cache: buildPermutations a second time (all hits), and the
//      whole `matbricks compile --scene` CLI run a second time;
//   c. cold compile time against scene size (1 .. 10000 distinct permutations), -j2;
//   d. GPU time of a specialized (folded) permutation against its feature-complete form, with
//      the features' inputs as constants and as run-time inputs (compiler/bench/cost.hpp, as
//      `matbricks bench`), and the three SPIR-V instruction counts.
// Usage: mb_bench_compile REPEATS MAX_SIZE OUT_DIR SCENE  (writes OUT_DIR/compile.{json,md}).
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
#include <nlohmann/json.hpp>
#include <thread>

#include "bench/cost.hpp"
#include "compile/build.hpp"
#include "compile/glsl_compiler.hpp"
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
  for (const auto& e : fs::directory_iterator(fs::path(MB_SOURCE_DIR) / "materials"))
    if (e.path().extension() == ".json") out.push_back(loadMaterialJson(e.path().string(), lib));
  std::sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.name < b.name; });
  return out;
}

const MaterialDesc& byName(const std::vector<MaterialDesc>& materials, const std::string& name) {
  for (const auto& m : materials)
    if (m.name == name) return m;
  throw std::runtime_error("no example material " + name);
}

// A realistic list: every example material at one and at three light types, with no
// environment and with SH, where its model shades them.
std::vector<Permutation> throughputList(const ShaderLibrary& lib, const std::vector<MaterialDesc>& materials) {
  std::vector<Permutation> perms;
  for (const auto& m : materials) {
    const ShadingModel* model = lib.findModel(m.model);
    auto has = [](const std::vector<std::string>& v, const std::string& x) {
      return std::find(v.begin(), v.end(), x) != v.end();
    };
    for (std::vector<std::string> lights : {std::vector<std::string>{"dir"}, {"dir", "point", "spot"}})
      for (std::string env : {"none", "sh"}) {
        if (!has(model->environments, env) ||
            !std::all_of(lights.begin(), lights.end(), [&](auto& l) { return has(model->lights, l); }))
          continue;
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

json benchThroughput(const ShaderLibrary& lib, const std::vector<Permutation>& perms, int repeats,
                     const fs::path& tmp) {
  json out{{"permutations", perms.size()}};
  for (unsigned jobs : {1u, 2u}) {
    BuildStats stats;
    double ms = bench::median(timeRepeats(repeats, [&] { buildPermutations(lib, perms, options(jobs), &stats); }));
    out["in_process_j" + std::to_string(jobs)] = json{{"ms_median", ms},
                                                      {"permutations_per_s", perms.size() * 1000.0 / ms},
                                                      {"compiled", stats.compiled},
                                                      {"unique_spirv", stats.uniqueSpirv}};
    double ext = bench::median(
        timeRepeats(repeats, [&] { externalPairsMs(lib, perms, tmp / ("ext" + std::to_string(jobs)), jobs); }));
    out["process_pairs_j" + std::to_string(jobs)] =
        json{{"ms_median", ext}, {"permutations_per_s", perms.size() * 1000.0 / ext}};
    out["speedup_j" + std::to_string(jobs)] = ext / ms;
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

json costOf(harness::VulkanHarness& gpu, const ShaderLibrary& lib, const Permutation& perm,
            const bench::CostOptions& o) {
  ProbeProgram probe = buildPermutationProbe(lib, perm);
  BenchProbeOptions timedOpt, baseOpt;
  timedOpt.iterations = baseOpt.iterations = o.iterations;
  baseOpt.baseline = true;
  EmittedShader timed = emitPermutationBenchProbe(lib, perm, timedOpt),
                base = emitPermutationBenchProbe(lib, perm, baseOpt);
  bench::CostMeasurement c =
      bench::measureCost(gpu, compileComputeGlsl(timed.glsl, timed.fileName),
                         compileComputeGlsl(base.glsl, base.fileName), probe.shader.layout, probe.domain, o);
  return {{"key", perm.key()},
          {"ns_per_eval", c.nsPerEval},
          {"ns_per_eval_min", c.nsPerEvalMin},
          {"records_per_dispatch", c.records},
          {"gpu_timestamps", c.gpuTimestamps},
          {"spirv_instructions", spirvInstructionCount(probe.compiled.spirv)}};
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
  o.repeats = std::max<uint32_t>(9, static_cast<uint32_t>(repeats));  // cost.hpp default: ns figures need more
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
    const double base = sp["ns_per_eval"].get<double>();
    rows.push_back({{"material", c.material},
                    {"specialized", sp},
                    {"feature_complete_constant", jc},
                    {"feature_complete_runtime", jr},
                    {"time_ratio_constant_over_specialized", jc["ns_per_eval"].get<double>() / base},
                    {"time_ratio_runtime_over_specialized", jr["ns_per_eval"].get<double>() / base}});
    std::cerr << "  runtime: " << c.material << " done\n";
  }
  return json{
      {"device", gpu.deviceName()}, {"iterations_per_record", o.iterations}, {"repeats", o.repeats}, {"rows", rows}};
}

std::string fmt(double v, int digits = 3) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

std::string markdown(const json& r) {
  std::string s = "# Compile benchmarks\n\n" + r["command"].get<std::string>() +
                  "\n\nMachine: " + r["machine"].get<std::string>() + "\n\n";
  const json& t = r["throughput"];
  s += "## a. Throughput (" + std::to_string(t["permutations"].get<size_t>()) +
       " permutations)\n\n"
       "| jobs | in-process perm/s | process pairs perm/s | speedup |\n|---|---|---|---|\n";
  for (int j : {1, 2}) {
    std::string k = std::to_string(j);
    s += "| " + k + " | " + fmt(t["in_process_j" + k]["permutations_per_s"]) + " | " +
         fmt(t["process_pairs_j" + k]["permutations_per_s"]) + " | " + fmt(t["speedup_j" + k]) + " |\n";
  }
  const json& n = r["noop"];
  s += "\n## b. No-op rebuild, warm cache\n\n| what | cold ms | warm ms |\n|---|---|---|\n| buildPermutations, " +
       std::to_string(n["permutations"].get<size_t>()) + " permutations, -j2 | " + fmt(n["cold_ms"]) + " | " +
       fmt(n["warm_ms_median"]) + " |\n";
  if (n.contains("cli"))
    s += "| `" + n["cli"]["command"].get<std::string>() + "` | " + fmt(n["cli"]["cold_ms"]) + " | " +
         fmt(n["cli"]["noop_ms_median"]) + " |\n";
  s +=
      "\n## c. Cold compile time against scene size (-j2)\n\n| permutations | repeats | ms | ms per permutation | peak RSS MiB |\n|---|---|---|---|---|\n";
  for (const auto& row : r["scaling"])
    s += "| " + std::to_string(row["permutations"].get<size_t>()) + " | " + std::to_string(row["repeats"].get<int>()) +
         " | " + fmt(row["ms_median"], 5) + " | " + fmt(row["ms_per_permutation"]) + " | " + fmt(row["peak_rss_mib"]) +
         " |\n";
  s +=
      "\n## d. Specialized against feature-complete, on " + r["runtime"]["device"].get<std::string>() +
      "\n\nns per evaluation (ratio to specialized) and SPIR-V instructions after spirv-opt. Full (constants): every "
      "feature on, the folded or absent features' inputs compile-time constants at the scene's values. Full (run-time): "
      "the same inputs read from the record, as a uniform-driven uber shader.\n\n"
      "| material | specialized | full (constants) | full (run-time) | instr. specialized | full (constants) | full (run-time) |\n"
      "|---|---|---|---|---|---|---|\n";
  auto instr = [](const json& j) { return std::to_string(j["spirv_instructions"].get<size_t>()); };
  for (const auto& row : r["runtime"]["rows"])
    s += "| " + row["material"].get<std::string>() + " | " + fmt(row["specialized"]["ns_per_eval"]) + " ns | " +
         fmt(row["feature_complete_constant"]["ns_per_eval"]) + " ns (" +
         fmt(row["time_ratio_constant_over_specialized"]) + "x) | " +
         fmt(row["feature_complete_runtime"]["ns_per_eval"]) + " ns (" +
         fmt(row["time_ratio_runtime_over_specialized"]) + "x) | " + instr(row["specialized"]) + " | " +
         instr(row["feature_complete_constant"]) + " | " + instr(row["feature_complete_runtime"]) + " |\n";
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = argc > 1 ? std::atoi(argv[1]) : 5;
  size_t maxSize = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 10000;
  fs::path outDir = argc > 3 ? argv[3] : "bench/results";
  std::string scene = argc > 4 ? argv[4] : "";
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
                   outDir.string() + " " + scene;
    r["machine"] = std::to_string(std::thread::hardware_concurrency()) + " hardware threads";
    r["toolchain"] = toolchainVersion();
    std::cerr << "a. throughput\n";
    r["throughput"] = benchThroughput(lib, perms, repeats, tmp);
    std::cerr << "b. no-op rebuild\n";
    r["noop"] = benchNoop(lib, perms, repeats, tmp, cli, scene);
    std::cerr << "c. scaling\n";
    r["scaling"] = benchScaling(lib, byName(materials, "filament_plastic"), maxSize, repeats, tmp);
    std::cerr << "d. run time\n";
    r["runtime"] = benchRuntime(lib, materials, repeats);
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
