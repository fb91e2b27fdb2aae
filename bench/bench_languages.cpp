// What it costs to execute each language validate runs (docs/targets.md "Executed"), and the
// error each gives: every validation permutation of the given materials (every light of the
// model together, every environment mode), fp32, in spirv, hlsl, glsl450 and essl310, on one
// set of seeded records per permutation, in one process (so every language shares the
// machine's load). Per permutation and language:
//   build_ms      emit + glslang + spirv-opt (probe cache off) + the translation: SPIRV-Cross,
//                 and for hlsl glslang's HLSL front end
//   first_ms      Vulkan: pipeline creation is inside kernelFor, the JIT in the first dispatch;
//                 GL: the driver's compile and link plus the first dispatch
//   run_ms        the records' dispatch (Vulkan: timestamps; GL: host time incl. read-back)
//   error_ratio   the largest |gpu - ref| / allowed over all values (1 = at the tolerance)
// Medians over the permutations per language, with the largest error ratio.
//
// Usage: mb_bench_languages SAMPLES FILE...
// Prints JSON.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>

#include "bench_stats.hpp"
#include "load/material_desc.hpp"
#include "permute/permutation.hpp"
#include "validate/probe_language.hpp"

using namespace mb;

namespace {

using mb::bench::median;

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: mb_bench_languages SAMPLES FILE...\n";
    return 2;
  }
  const uint64_t samples = std::stoull(argv[1]);
  setProbeCacheDir("");  // every build compiles: the cost a first validation pays
  ShaderLibrary lib = ShaderLibrary::load(ShaderLibrary::defaultRoot());
  std::vector<MaterialDesc> materials;
  for (int i = 2; i < argc; ++i)
    for (auto& m : loadMaterialFile(argv[i], lib)) materials.push_back(std::move(m));
  std::vector<Permutation> perms;
  for (const auto& m : materials)
    for (auto& p : validationPermutationsFor(m, lib)) perms.push_back(std::move(p));

  harness::VulkanHarness vulkan;
  gl::GlCompute gl45(gl::GlApi::Gl45Core), es31(gl::GlApi::Es31);
  nlohmann::json out;
  out["samples"] = samples;
  out["permutations"] = perms.size();
  out["vulkan_device"] = vulkan.deviceName();
  out["gl_device"] = gl45.deviceName();
  out["gles_device"] = es31.deviceName();
  for (const auto& name : executableLanguages()) {
    const ProbeLanguage language = *parseProbeLanguage(name);
    const ProbeDevices devices{&vulkan, language == ProbeLanguage::Essl310 ? &es31 : &gl45};
    std::vector<double> build, first, run, ratio;
    nlohmann::json rows = nlohmann::json::array();
    uint64_t failed = 0;
    for (const auto& perm : perms) {
      const LanguageProbe p = buildPermutationProbeIn(lib, perm, language);
      const ValidationRecord r = validateProbe(devices, p, "permutation", samples, 1);
      build.push_back(r.compileMs);
      first.push_back(r.firstDispatchMs);
      run.push_back(r.gpuMs);
      ratio.push_back(r.stats.worstRatio);
      failed += !r.passed();
      rows.push_back({{"key", r.key},
                      {"build_ms", r.compileMs},
                      {"first_ms", r.firstDispatchMs},
                      {"run_ms", r.gpuMs},
                      {"reference_ms", r.referenceMs},
                      {"max_abs_error", r.stats.maxAbs},
                      {"max_rel_error", r.stats.maxRel},
                      {"error_ratio", r.stats.worstRatio},
                      {"passed", r.passed()}});
    }
    out["languages"][name] = {{"build_ms_median", median(build)},
                              {"first_ms_median", median(first)},
                              {"run_ms_median", median(run)},
                              {"error_ratio_median", median(ratio)},
                              {"error_ratio_max", *std::max_element(ratio.begin(), ratio.end())},
                              {"failed", failed},
                              {"permutations", rows}};
  }
  std::cout << out.dump(2) << "\n";
  return 0;
}
