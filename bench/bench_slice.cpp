// Vertical-slice benchmark (issue: end-to-end slice). Measures, on this machine:
//   1. compile time per permutation: in-process (glslang + spirv-val + spirv-opt APIs)
//      against one glslangValidator + spirv-opt process pair per permutation;
//   2. validation time per permutation (emit + compile + GPU run + reference + compare);
//   3. ns per BRDF evaluation on the Vulkan device (warm pipeline, large dispatch).
// Prints JSON to stdout. Medians of repeats; ratios are taken within the same run.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "bench_stats.hpp"
#include "core/data_dir.hpp"
#include "compile/glsl_compiler.hpp"
#include "emit/emitter.hpp"
#include "permute/permutation.hpp"
#include "validate/validation.hpp"

using namespace mb;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

static double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

using mb::bench::median;

int main(int argc, char** argv) {
  int repeats = argc > 1 ? std::atoi(argv[1]) : 9;
  uint64_t evalCount = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1u << 20;
  ShaderLibrary lib = ShaderLibrary::load(ShaderLibrary::defaultRoot());
  std::vector<MaterialDesc> materials;
  for (const auto& e : fs::directory_iterator(mb::compiledSourceDir() / "materials"))
    if (e.path().extension() == ".json") materials.push_back(loadMaterialJson(e.path().string(), lib));
  std::sort(materials.begin(), materials.end(), [](auto& a, auto& b) { return a.name < b.name; });
  auto perms = permutationsFor(materials);

  harness::VulkanHarness gpu;
  nlohmann::json out{{"device", gpu.deviceName()},
                     {"repeats", repeats},
                     {"eval_count", evalCount},
                     {"toolchain", toolchainVersion()},
                     {"permutations", nlohmann::json::array()}};
  fs::path tmp = fs::temp_directory_path() / ("mb_bench_" + std::to_string(::getpid()));
  fs::create_directories(tmp);

  // Pay glslang's one-time process initialization before timing (it is per process, not
  // per permutation; it is reported separately).
  auto tInit = Clock::now();
  compileComputeGlsl(emitPermutation(lib, perms.front()).glsl, "warmup.glsl");
  out["first_compile_in_process_ms"] = msSince(tInit);

  for (const auto& perm : perms) {
    EmittedShader s = emitPermutation(lib, perm);
    std::vector<double> inProc, external, validation;
    fs::path src = tmp / (s.key + ".comp");
    { std::ofstream(src, std::ios::binary) << s.glsl; }
    std::string cmd = "glslangValidator -V --target-env vulkan1.1 -o " + (tmp / "a.spv").string() + " " + src.string() +
                      " >/dev/null && spirv-opt -O --target-env=vulkan1.1 " + (tmp / "a.spv").string() + " -o " +
                      (tmp / "b.spv").string();
    for (int r = 0; r < repeats; ++r) {
      auto t0 = Clock::now();
      compileComputeGlsl(s.glsl, s.fileName);
      inProc.push_back(msSince(t0));
      t0 = Clock::now();
      if (std::system(cmd.c_str()) != 0) {
        std::cerr << "external compile failed: " << cmd << "\n";
        return 1;
      }
      external.push_back(msSince(t0));
      t0 = Clock::now();
      ValidationRecord rec = validateProbe(gpu, buildPermutationProbe(lib, perm), "permutation", 4096, 1);
      validation.push_back(msSince(t0));
      if (!rec.passed()) std::cerr << "warning: " << rec.key << " did not validate\n";
    }

    // ns per evaluation: one warm-up dispatch (lavapipe JIT-compiles at first dispatch),
    // then the median over repeats of the timestamped dispatch of evalCount records.
    ProbeProgram prog = buildPermutationProbe(lib, perm);
    SampleDomain domain = prog.domain;
    std::vector<float> inputs = generateSamples(prog.shader.layout, domain, evalCount, 2);
    auto kernel = gpu.createKernel(prog.compiled.spirv, 0, prog.shader.readsTable);
    const auto* table = prog.tableBuffer();
    gpu.run(*kernel, inputs, prog.shader.layout.inStride, prog.shader.layout.outStride, evalCount, {}, table);
    std::vector<double> nsPerEval;
    for (int r = 0; r < repeats; ++r) {
      auto res =
          gpu.run(*kernel, inputs, prog.shader.layout.inStride, prog.shader.layout.outStride, evalCount, {}, table);
      nsPerEval.push_back(res.gpuMs * 1e6 / double(evalCount));
    }
    out["permutations"].push_back({{"key", s.key},
                                   {"compile_in_process_ms_median", median(inProc)},
                                   {"compile_glslangValidator_plus_spirv_opt_processes_ms_median", median(external)},
                                   {"speedup_in_process", median(external) / median(inProc)},
                                   {"validate_4096_samples_ms_median", median(validation)},
                                   {"ns_per_eval_median", median(nsPerEval)},
                                   {"spirv_instructions", spirvInstructionCount(prog.compiled.spirv)}});
  }
  fs::remove_all(tmp);
  std::cout << out.dump(2) << "\n";
  return 0;
}
