// Where a permutation's largest relative error comes from (issue 14, item 7). For every
// permutation `matbricks validate` runs on the given materials (same samples: 4096, seed 1),
// the record with the largest relative error (floor 1e-6, as validate's max_rel) is printed
// with its GPU and reference values and its input-conditioning allowance, then re-run with the
// light sources switched off one group at a time (each light's intensity, or the environment's
// SH and prefiltered radiance, set to 0; the directional light has no intensity column and is
// what remains when all others are off), so the term that carries the error shows; then, on
// the variant that keeps the error, each material input (and ngTilt, tangentAngle) at 0 in
// turn. JSON lines.
// Usage: mb_bench_permutation_errors material.json ... > permutation_errors.jsonl
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "harness/vulkan_harness.hpp"
#include "library/shader_library.hpp"
#include "load/material_desc.hpp"
#include "permute/permutation.hpp"
#include "validate/sampler.hpp"
#include "validate/validation.hpp"

using namespace mb;
using nlohmann::json;

namespace {

// Largest |gpu - ref| / max(|ref|, 1e-6) of one record, over its output components.
double recordRel(const ProbeRun& run, uint64_t i, uint32_t stride, uint32_t outputs) {
  double worst = 0;
  for (uint32_t k = 0; k < outputs; ++k) {
    double ref = run.reference[i * stride + k];
    worst = std::max(worst, std::abs(run.gpu[i * stride + k] - ref) / std::max(std::abs(ref), 1e-6));
  }
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  ShaderLibrary lib = ShaderLibrary::load(ShaderLibrary::defaultRoot());
  harness::VulkanHarness gpu;
  for (int a = 1; a < argc; ++a) {
    MaterialDesc m = loadMaterialJson(argv[a], lib);
    for (const Permutation& p : validationPermutationsFor(m, lib)) {
      Permutation perm = p;
      perm.material = &m;
      ProbeProgram program = buildPermutationProbe(lib, perm);
      const ProbeLayout& layout = program.shader.layout;
      std::vector<float> inputs = generateSamples(layout, program.domain, 4096, 1);
      ProbeRun run = runProbe(gpu, program, inputs);
      const uint32_t stride = layout.outStride, outputs = 3;
      uint64_t worst = 0;
      for (uint64_t i = 1; i < run.count; ++i)
        if (recordRel(run, i, stride, outputs) > recordRel(run, worst, stride, outputs)) worst = i;
      std::vector<std::string> cols = layout.columns();
      std::vector<float> record(inputs.begin() + worst * layout.inStride,
                                inputs.begin() + (worst + 1) * layout.inStride);
      json out{{"key", program.shader.key}, {"max_rel", recordRel(run, worst, stride, outputs)}};
      json in = json::object();
      for (size_t k = 0; k < cols.size(); ++k) in[cols[k]] = record[k];
      out["input"] = in;
      out["gpu"] = {run.gpu[worst * stride], run.gpu[worst * stride + 1], run.gpu[worst * stride + 2]};
      out["reference"] = {run.reference[worst * stride], run.reference[worst * stride + 1],
                          run.reference[worst * stride + 2]};
      out["conditioning"] = {run.conditioning[worst * stride], run.conditioning[worst * stride + 1],
                             run.conditioning[worst * stride + 2]};
      out["tolerance"] = {{"abs", program.tolerance.abs}, {"rel", program.tolerance.rel}};
      // Groups of columns that carry each light source's radiance.
      std::vector<std::pair<std::string, std::vector<std::string>>> groups;
      for (const char* light : {"point", "spot", "sphere", "tube"}) {
        std::vector<std::string> c;
        for (const auto& name : cols)
          if (name.rfind(std::string(light) + "Intensity", 0) == 0) c.push_back(name);
        if (!c.empty()) groups.push_back({light, c});
      }
      std::vector<std::string> env;
      for (const auto& name : cols)
        if ((name.size() > 2 && name.rfind("sh", 0) == 0 && std::isdigit(static_cast<unsigned char>(name[2]))) ||
            name.rfind("prefiltered", 0) == 0)
          env.push_back(name);
      if (!env.empty()) groups.push_back({"environment", env});
      // Variant "only X": every other group zeroed (the directional light always stays on).
      json only = json::object();
      std::vector<std::string> names{"dir"};
      for (const auto& g : groups) names.push_back(g.first);
      std::vector<float> batch;
      for (const auto& keep : names) {
        std::vector<float> r = record;
        for (const auto& g : groups)
          if (g.first != keep)
            for (const auto& c : g.second) r[std::find(cols.begin(), cols.end(), c) - cols.begin()] = 0.0f;
        batch.insert(batch.end(), r.begin(), r.end());
      }
      ProbeRun parts = runProbe(gpu, program, batch);
      for (size_t v = 0; v < names.size(); ++v) {
        double absErr = 0, ref = 0;
        for (uint32_t k = 0; k < outputs; ++k) {
          absErr = std::max(absErr, std::abs(parts.gpu[v * stride + k] - parts.reference[v * stride + k]));
          ref = std::max(ref, std::abs(parts.reference[v * stride + k]));
        }
        only[names[v] + (names[v] == "dir" ? "" : " + dir")] = {
            {"max_abs", absErr}, {"max_reference", ref}, {"max_rel", recordRel(parts, v, stride, outputs)}};
      }
      out["only"] = only;
      // On the variant that keeps the error, each other input column at 0 in turn (material
      // inputs, the frame's ngTilt and tangentAngle): which one the error needs.
      size_t carrier = 0;
      for (size_t v = 1; v < names.size(); ++v)
        if (recordRel(parts, v, stride, outputs) > recordRel(parts, carrier, stride, outputs)) carrier = v;
      std::vector<float> base(batch.begin() + carrier * layout.inStride,
                              batch.begin() + (carrier + 1) * layout.inStride);
      std::vector<std::string> zeroed;
      std::vector<float> zbatch;
      for (size_t k = 0; k < cols.size(); ++k) {
        const std::string& c = cols[k];
        bool lightOrGeometry = c.size() > 1 && c[1] == '.';  // n.x, v.y, l.z
        for (const auto& g : groups)
          for (const auto& gc : g.second) lightOrGeometry = lightOrGeometry || gc == c;
        for (const char* light : {"point", "spot", "sphere", "tube", "dfg", "ao"})
          lightOrGeometry = lightOrGeometry || c.rfind(light, 0) == 0;
        if (lightOrGeometry || base[k] == 0.0f) continue;
        std::vector<float> r = base;
        r[k] = 0.0f;
        zeroed.push_back(c);
        zbatch.insert(zbatch.end(), r.begin(), r.end());
      }
      json atZero = json::object();
      if (!zbatch.empty()) {
        ProbeRun z = runProbe(gpu, program, zbatch);
        for (size_t v = 0; v < zeroed.size(); ++v) atZero[zeroed[v]] = recordRel(z, v, stride, outputs);
      }
      out["carrier"] = names[carrier];
      out["carrier_with_input_at_zero"] = atZero;
      std::printf("%s\n", out.dump().c_str());
      std::fflush(stdout);
    }
  }
  return 0;
}
