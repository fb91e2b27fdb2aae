// The permutation reference resolved once (ReferenceLookup::Resolved: each role's brick
// reference, each input and the scene's record columns found when the closure is built)
// against the by-name path it replaces (every name looked up per record and per brick call):
// the same doubles, bit for bit, on every record, with and without the input-conditioning
// skew, so that validate's verdicts cannot change (docs/performance-validate.md).
#include <catch2/catch.hpp>

#include <bit>
#include <cstring>

#include "common/model_reference.hpp"
#include "common/reference.hpp"
#include "permute/permutation.hpp"
#include "support/pipeline_support.hpp"
#include "validate/probe_program.hpp"
#include "validate/sampler.hpp"

using namespace mb;

namespace {

// Records as the reference reads them: sampled inputs, then the fed outputs (what surface
// code computed on the GPU; here deterministic values in [0.05, 0.95], as no GPU runs).
std::vector<double> records(const ProbeProgram& p, uint64_t count) {
  const ProbeLayout& layout = p.shader.layout;
  const std::vector<float> inputs = generateSamples(layout, p.domain, count, 7);
  const uint32_t stride = layout.inStride + layout.fedCount();
  std::vector<double> out(count * stride);
  for (uint64_t i = 0; i < count; ++i) {
    for (uint32_t k = 0; k < layout.inStride; ++k) out[i * stride + k] = inputs[i * layout.inStride + k];
    for (uint32_t k = 0; k < layout.fedCount(); ++k)
      out[i * stride + layout.inStride + k] = 0.05 + 0.9 * ((i * 37 + k * 11) % 101) / 100.0;
  }
  return out;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// Evaluates both closures on every record, plain and under the skew validate's allowance
// applies (ref::ScopedHalfVectorSumSkew), and requires bit-identical outputs. Returns the
// number of values compared.
size_t requireSameDoubles(const ProbeProgram& p, const std::function<void(const double*, double*)>& resolved,
                          const std::function<void(const double*, double*)>& byName, uint64_t count) {
  const ProbeLayout& layout = p.shader.layout;
  const uint32_t stride = layout.inStride + layout.fedCount();
  const std::vector<double> in = records(p, count);
  std::vector<double> a(layout.outStride), b(layout.outStride);
  size_t compared = 0, differing = 0;
  for (double skew : {0.0, 2 * 0x1p-23}) {
    ref::ScopedHalfVectorSumSkew scoped(skew);
    for (uint64_t i = 0; i < count; ++i) {
      std::fill(a.begin(), a.end(), -1.0);
      std::fill(b.begin(), b.end(), -1.0);
      resolved(in.data() + i * stride, a.data());
      byName(in.data() + i * stride, b.data());
      compared += a.size();
      if (!sameBits(a, b)) ++differing;
    }
  }
  INFO(p.shader.key << ": " << differing << " records differ");
  CHECK(differing == 0);
  return compared;
}

std::map<std::string, std::string> boundBricks(const ShaderLibrary& lib, const Permutation& perm) {
  std::map<std::string, std::string> bricks;
  for (const auto& [role, id] : boundRoles(lib, perm)) bricks[role] = id;
  return bricks;
}

// Every validation permutation of `materials`, in the modes validate runs (and with the
// illuminance as an input), `count` records each, and `truthCount` with the ground truths
// bench's yardstick uses (numerical integrals, ~1000x slower).
void sweep(const std::vector<std::string>& materials, uint64_t count, uint64_t truthCount) {
  const ShaderLibrary& lib = test::shippedLibrary();
  size_t permutations = 0, values = 0;
  for (const auto& name : materials) {
    MaterialDesc m = test::shippedMaterial(name);
    for (const auto& perm : validationPermutationsFor(m, lib)) {
      for (bool illuminanceInput : {false, true}) {
        ProbeProgram p = describePermutationProbe(lib, perm, illuminanceInput);
        for (bool groundTruths : {false, true}) {
          auto resolved = materialReferenceEval(perm, p.shader.layout, boundBricks(lib, perm), groundTruths,
                                                illuminanceInput, ReferenceLookup::Resolved, p.ltcTable);
          auto byName = materialReferenceEval(perm, p.shader.layout, boundBricks(lib, perm), groundTruths,
                                              illuminanceInput, ReferenceLookup::ByName, p.ltcTable);
          values += requireSameDoubles(p, resolved, byName, groundTruths ? truthCount : count);
        }
        // What validate itself runs: the program's own reference is the resolved one.
        values += requireSameDoubles(p, p.reference,
                                     materialReferenceEval(perm, p.shader.layout, boundBricks(lib, perm), false,
                                                           illuminanceInput, ReferenceLookup::ByName, p.ltcTable),
                                     count);
      }
      ++permutations;
    }
  }
  INFO(permutations << " permutations, " << values << " values compared");
  CHECK(permutations > 0);
}

std::vector<std::string> shippedMaterialNames() {
  std::vector<std::string> names;
  for (const auto& f : test::exampleMaterialFiles()) names.push_back(std::filesystem::path(f).stem().string());
  return names;
}

}  // namespace

TEST_CASE("the resolved reference gives the by-name path's doubles on every shipped material",
          "[validate][reference-resolved]") {
  // Every permutation validate runs on materials/*.json: both models, every feature, every
  // light type and environment mode, surface code with fed outputs (worn_car_paint).
  sweep(shippedMaterialNames(), 256, 2);
}

TEST_CASE("the resolved reference gives the by-name path's doubles on 4096 records per permutation",
          "[.reference-resolved-sweep]") {
  sweep(shippedMaterialNames(), 4096, 32);
}

TEST_CASE("a resolved input of the wrong size or a missing brick throws as by name", "[validate][reference-resolved]") {
  ref::ModelEvalInput e;
  e.inputs["roughness"] = {0.5, 0.5};  // neither float nor vec3
  e.bricks["roughness"] = "no_such_brick";
  e.resolve();
  CHECK_THROWS_WITH(e.floatInput("roughness"), "model input 'roughness' missing or not a float");
  CHECK_THROWS_WITH(e.vec3Input("baseColor"), "model input 'baseColor' missing or not a vec3");
  CHECK_THROWS_WITH(e.scalar("roughness", ref::Args() << 0.5), "brick 'no_such_brick' has no reference");
  CHECK_THROWS_WITH(e.scalar("diffuse", ref::Args() << 0.5), "no brick bound to role 'diffuse'");
}
