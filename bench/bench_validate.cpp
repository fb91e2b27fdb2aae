// Validation time per permutation (issue 15, item 3): what `matbricks validate` spends on one
// permutation of 4096 samples, stage by stage, on the current path and on the path before
// issue 15 (both selectable, measured in one run), with every cache state that matters:
//
//   new_cold    fresh probe cache and fresh Mesa shader cache: glslang + spirv-opt and
//               lavapipe's JIT both run (the first validation of a permutation anywhere);
//   new_warm    a second harness (as a second `validate` process would open), the probe
//               SPIR-V and Mesa's JIT output now on disk;
//   new_again   the same harness once more: the kernel, JIT-compiled, is reused in-process;
//   old_cold    the path before: no probe cache, a new pipeline per run whose first dispatch
//               (the JIT) lies inside the timestamps, the conditioning allowance computed
//               for every value, on one thread; Mesa's shader cache fresh again;
//   old_warm    the same with Mesa's shader cache warm (what the old `validate` measured
//               on a machine that had validated the permutation before). Run once.
//
// Also: the process-start-to-first-verdict time of the first permutation (device open,
// glslang initialization, compile, JIT, run, reference), and gpu_ms of textured against
// untextured permutations (glTF materials whose surface code reads a texture input).
//
// Usage: mb_bench_validate REPEATS SAMPLES FILE...   (materials or glTF files; REPEATS of
// new_again, whose median is reported)
// Prints JSON. Medians over the permutations and over repeats; one process, so old and new
// share the machine's load.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <thread>
#include <time.h>
#include <unistd.h>

#include "bench_stats.hpp"
#include "compile/glsl_compiler.hpp"
#include "compile/shader_cache.hpp"
#include "permute/axes.hpp"
#include "permute/permutation.hpp"
#include "validate/validation.hpp"

using namespace mb;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

const Clock::time_point kProcessStart = Clock::now();

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// CPU time of the whole process (all threads: the reference's and lavapipe's), in ms. On this
// shared 2-core VM wall times stretch with other people's load; CPU time much less so.
double processCpuMs() {
  timespec ts{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

using mb::bench::median;

// A glTF texture becomes a user parameter named after it (load/gltf_mapping.cpp).
bool textured(const MaterialDesc& m) {
  return std::any_of(m.params.begin(), m.params.end(),
                     [](const MaterialParam& p) { return p.user && p.name.find("Texture") != std::string::npos; });
}

struct Stages {
  double emitAndCompileMs = 0;  // buildPermutationProbe: emit, compile (or cache), reference setup
  double compileMs = 0;         // its compile part
  double samplesMs = 0;
  double pipelineMs = 0;  // createKernel / kernelFor
  double firstDispatchMs = 0;
  double gpuMs = 0;      // timestamped dispatch
  double gpuWallMs = 0;  // run() host time, warm-up included
  double referenceMs = 0;
  double compareMs = 0;
  double totalMs = 0;
  double cpuMs = 0;  // process CPU time over the whole validation
  bool passed = false;
  uint64_t failures = 0;
  uint64_t passedByConditioning = 0;
  int64_t worstRecord = -1;

  nlohmann::json json() const {
    return {{"emit_compile_ms", emitAndCompileMs},
            {"compile_ms", compileMs},
            {"samples_ms", samplesMs},
            {"pipeline_ms", pipelineMs},
            {"first_dispatch_ms", firstDispatchMs},
            {"gpu_ms", gpuMs},
            {"gpu_wall_ms", gpuWallMs},
            {"reference_ms", referenceMs},
            {"compare_ms", compareMs},
            {"total_ms", totalMs},
            {"cpu_ms", cpuMs},
            {"passed", passed},
            {"failures", failures},
            {"passed_by_conditioning", passedByConditioning},
            {"worst_record", worstRecord}};
  }
};

// One validation of `perm`, the steps of validateProbe timed one by one. `old`: the path
// before issue 15 (the caller also turned the probe cache off and opened the harness without
// the warm-up dispatch).
Stages validateOnce(harness::VulkanHarness& gpu, const ShaderLibrary& lib, const Permutation& perm, uint64_t samples,
                    bool old) {
  Stages s;
  const auto t0 = Clock::now();
  const double cpu0 = processCpuMs();
  auto t = Clock::now();
  ProbeProgram program = buildPermutationProbe(lib, perm);
  s.emitAndCompileMs = msSince(t);
  s.compileMs = program.compileMs;
  t = Clock::now();
  std::vector<float> inputs = generateSamples(program.shader.layout, program.domain, samples, 1);
  s.samplesMs = msSince(t);
  t = Clock::now();
  const bool table = program.shader.readsTable;
  auto kernel = old ? gpu.createKernel(program.compiled.spirv, 0, table) : gpu.kernelFor(program.compiled.spirv, table);
  s.pipelineMs = msSince(t);
  t = Clock::now();
  const ProbeLayout& layout = program.shader.layout;
  harness::RunResult result =
      gpu.run(*kernel, inputs, layout.inStride, layout.outStride, samples, {}, program.tableBuffer());
  s.gpuWallMs = msSince(t);
  s.gpuMs = result.gpuMs;
  s.firstDispatchMs = result.firstDispatchMs;
  ProbeRun run;
  run.count = samples;
  run.gpu = std::move(result.outputs);
  run.inputs = std::move(inputs);
  t = Clock::now();
  ReferenceOptions options = validationOptions();
  if (old) {
    options.onlyWhereNeeded = false;
    options.threads = 1;
  }
  computeReference(run, program, options);
  s.referenceMs = msSince(t);
  t = Clock::now();
  ErrorStats stats = compare(run, program);
  s.compareMs = msSince(t);
  s.totalMs = msSince(t0);
  s.cpuMs = processCpuMs() - cpu0;
  s.passed = stats.passed() && stats.negativeCount == 0;
  s.failures = stats.failures;
  s.passedByConditioning = stats.passedByConditioning;
  s.worstRecord = stats.worstRecord;
  return s;
}

// A new, empty Mesa shader cache for the harnesses opened after this call (Mesa reads the
// variable when it creates the device's disk cache).
void freshMesaCache(const fs::path& dir) {
  fs::create_directories(dir);
  ::setenv("MESA_SHADER_CACHE_DIR", dir.c_str(), 1);
  ::unsetenv("MESA_SHADER_CACHE_DISABLE");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: mb_bench_validate REPEATS SAMPLES FILE...\n";
    return 2;
  }
  const int repeats = std::max(1, std::atoi(argv[1]));
  const uint64_t samples = std::strtoull(argv[2], nullptr, 10);
  const fs::path tmp = fs::temp_directory_path() / ("mb_bench_validate_" + std::to_string(::getpid()));
  freshMesaCache(tmp / "mesa_new");
  setProbeCacheDir(tmp / "probe_cache");

  ShaderLibrary lib = ShaderLibrary::load(ShaderLibrary::defaultRoot());
  std::vector<MaterialDesc> materials;
  for (int i = 3; i < argc; ++i)
    for (auto& m : loadMaterialFile(argv[i], lib)) materials.push_back(std::move(m));
  struct Item {
    Permutation perm;
    bool textured;
    bool gltf;  // from a glTF file: the standard model with the same bricks, so comparable
  };
  std::vector<Item> items;
  for (const auto& m : materials)
    for (auto& p : validationPermutationsFor(m, lib))
      if (!brokenBrickRule(*lib.findModel(m.model), p)) {
        const std::string ext = fs::path(m.sourceFile).extension().string();
        items.push_back({p, textured(m), ext == ".gltf" || ext == ".glb"});
      }

  nlohmann::json out{{"samples", samples},
                     {"repeats", repeats},
                     {"permutations", items.size()},
                     {"hardware_threads", std::thread::hardware_concurrency()},
                     {"toolchain", toolchainVersion()}};

  // new_cold, the first permutation timed from process start (before the device is opened).
  std::vector<Stages> newCold, newWarm, oldCold, oldWarm;
  std::vector<std::vector<Stages>> newAgain(items.size());
  // The GPU time of the 4096-record dispatch alone, median of kGpuRepeats warm dispatches: a
  // single dispatch of 1-3 ms swings by 2x with the load of this shared VM.
  constexpr int kGpuRepeats = 15;
  std::vector<double> gpuMedian(items.size());
  {
    harness::VulkanHarness gpu;
    out["device"] = gpu.deviceName();
    for (size_t i = 0; i < items.size(); ++i) {
      newCold.push_back(validateOnce(gpu, lib, items[i].perm, samples, false));
      if (i == 0) out["first_permutation_from_process_start_ms"] = msSince(kProcessStart);
    }
  }
  {
    harness::VulkanHarness gpu;  // a second process's harness: disk caches warm, no kernels
    for (size_t i = 0; i < items.size(); ++i) {
      newWarm.push_back(validateOnce(gpu, lib, items[i].perm, samples, false));
      for (int r = 0; r < repeats; ++r) newAgain[i].push_back(validateOnce(gpu, lib, items[i].perm, samples, false));
      ProbeProgram program = buildPermutationProbe(lib, items[i].perm);
      const ProbeLayout& layout = program.shader.layout;
      std::vector<float> inputs = generateSamples(layout, program.domain, samples, 1);
      auto kernel = gpu.kernelFor(program.compiled.spirv, program.shader.readsTable);
      std::vector<double> gpuMs;
      for (int r = 0; r < kGpuRepeats; ++r)
        gpuMs.push_back(
            gpu.run(*kernel, inputs, layout.inStride, layout.outStride, samples, {}, program.tableBuffer()).gpuMs);
      gpuMedian[i] = median(gpuMs);
    }
  }
  setProbeCacheDir("");
  freshMesaCache(tmp / "mesa_old");
  {
    harness::DeviceOptions o;
    o.warmUpFirstDispatch = false;
    harness::VulkanHarness gpu(o);
    for (const auto& it : items) oldCold.push_back(validateOnce(gpu, lib, it.perm, samples, true));
    // Once: the old path takes seconds per permutation on this VM.
    for (const auto& it : items) oldWarm.push_back(validateOnce(gpu, lib, it.perm, samples, true));
  }
  fs::remove_all(tmp);

  nlohmann::json perms = nlohmann::json::array();
  std::vector<double> tot[5], cpu[5], gpuRepeated[2], gpuTex[2], gpuOldTex[2], gpuOldWarmTex[2];
  bool verdictsAgree = true;
  for (size_t i = 0; i < items.size(); ++i) {
    Stages again = newAgain[i].front();
    std::vector<double> againTotals;
    for (const auto& s : newAgain[i]) againTotals.push_back(s.totalMs);
    again.totalMs = median(againTotals);
    std::vector<double> againCpu;
    for (const auto& s : newAgain[i]) againCpu.push_back(s.cpuMs);
    again.cpuMs = median(againCpu);
    const Stages* all[5] = {&newCold[i], &newWarm[i], &again, &oldCold[i], &oldWarm[i]};
    for (int k = 0; k < 5; ++k) {
      tot[k].push_back(all[k]->totalMs);
      cpu[k].push_back(all[k]->cpuMs);
    }
    for (const Stages* s : all)
      verdictsAgree = verdictsAgree && s->passed == oldCold[i].passed && s->failures == oldCold[i].failures &&
                      s->passedByConditioning == oldCold[i].passedByConditioning &&
                      s->worstRecord == oldCold[i].worstRecord;
    if (items[i].gltf) {
      gpuRepeated[items[i].textured].push_back(gpuMedian[i]);
      gpuTex[items[i].textured].push_back(newWarm[i].gpuMs);
      gpuOldTex[items[i].textured].push_back(oldCold[i].gpuMs);
      gpuOldWarmTex[items[i].textured].push_back(oldWarm[i].gpuMs);
    }
    perms.push_back({{"key", items[i].perm.key()},
                     {"textured", items[i].textured},
                     {"gltf", items[i].gltf},
                     {"gpu_ms_repeated_dispatch_median", gpuMedian[i]},
                     {"new_cold", newCold[i].json()},
                     {"new_warm", newWarm[i].json()},
                     {"new_again", again.json()},
                     {"old_cold", oldCold[i].json()},
                     {"old_warm", oldWarm[i].json()}});
  }
  const char* names[5] = {"new_cold", "new_warm", "new_again", "old_cold", "old_warm"};
  nlohmann::json med, cpuMed;
  for (int k = 0; k < 5; ++k) {
    med[names[k]] = median(tot[k]);
    cpuMed[names[k]] = median(cpu[k]);
  }
  out["total_ms_median"] = med;
  out["cpu_ms_median"] = cpuMed;
  // Pass/fail, failures, passed_by_conditioning and the worst record, old path against new.
  out["verdicts_agree"] = verdictsAgree;
  // Over the glTF permutations only (one model, the same bricks): textured against not.
  out["gltf_gpu_ms_median"] = {{"repeated_dispatch_untextured", median(gpuRepeated[0])},
                               {"repeated_dispatch_textured", median(gpuRepeated[1])},
                               {"new_untextured", median(gpuTex[0])},
                               {"new_textured", median(gpuTex[1])},
                               {"old_cold_untextured", median(gpuOldTex[0])},
                               {"old_cold_textured", median(gpuOldTex[1])},
                               {"old_warm_untextured", median(gpuOldWarmTex[0])},
                               {"old_warm_textured", median(gpuOldWarmTex[1])}};
  // Each stage's median over the permutations, per path: the breakdown.
  nlohmann::json stages;
  for (const char* mode : names) {
    std::map<std::string, std::vector<double>> values;
    for (const auto& p : perms)
      for (const auto& [k, v] : p[mode].items())
        if (v.is_number_float()) values[k].push_back(v.get<double>());
    for (auto& [k, v] : values) stages[mode][k] = median(v);
  }
  out["stage_ms_median"] = stages;
  out["per_permutation"] = perms;
  std::cout << out.dump(2) << "\n";
  return verdictsAgree ? 0 : 1;
}
