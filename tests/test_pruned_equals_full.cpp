// Pruned equals full (issue 5 item 3; DESIGN.md "Validation principles";
// docs/performance-compile.md "Pruned equals full"): every required permutation that folded a
// feature away, or has fewer features than its model, must shade the scene exactly as the
// feature-complete permutation (every feature on, set to the scene's values) does. Both run on
// lavapipe over the SAME fp32 records (the pruned layout's columns, mapped into the full one by
// name) and must agree within the sum of their two validated fp32 error allowances.
//
// Why that tolerance (not a picked number): each probe's allowance (its bricks' manifest
// tolerances, plus the input-conditioning term of runProbe) bounds |gpu - ref| for that probe,
// and validate checks it holds. When the fold is neutral the two double references are the
// same function, so by the triangle inequality |gpu_pruned - gpu_full| <= allowance_pruned +
// allowance_full. The references themselves are checked to agree to double rounding
// (kReferenceRel), which is what "neutral" means independently of fp32. A non-neutral fold
// (the negative control, clear coat 0.5) breaks both.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>

#include "compile/glsl_compiler.hpp"
#include "load/scene_desc.hpp"
#include "permute/scene_plan.hpp"
#include "permute/specialize.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"
#include "validate/probe_program.hpp"

using namespace mb;

namespace {

constexpr uint64_t kRecords = 2048;
// The double references of a permutation run at most a few thousand operations per output
// value (lights x lobes x brick terms); n * 2^-53 with n = 2^12 gives 2^-41. Relative to
// max(|ref|, kRelativeErrorFloor), as every other comparison in validate/.
constexpr double kReferenceRel = 0x1p-41;

struct PairStats {
  uint64_t values = 0;
  uint64_t failures = 0;           // GPU outputs outside the summed allowance
  uint64_t referenceMismatch = 0;  // double references differing beyond kReferenceRel
  double maxAbs = 0, maxRel = 0;   // |gpu_pruned - gpu_full|, and relative to the full's ref
  double maxRefRel = 0;            // |ref_pruned - ref_full| / max(|ref_full|, floor)
  double worstRatio = 0;           // max |gpu difference| / allowance
  size_t prunedInstructions = 0, fullInstructions = 0;
  bool prunedValid = false, fullValid = false;  // each against its own reference
};

// Allowance of one output value of one probe (ErrorStats::add's test).
double allowance(const Tolerance& tol, double ref, double conditioning) {
  return tol.abs + tol.rel * std::abs(ref) + conditioning;
}

// The value a use gives a record column ("clearCoat", "sheenColor.y"), if it names the input.
std::optional<double> useValue(const MaterialUse& use, const std::string& column) {
  size_t dot = column.find('.');
  std::string name = column.substr(0, dot);
  size_t component = dot == std::string::npos ? 0 : std::string("xyz").find(column[dot + 1]);
  auto it = use.values.find(name);
  if (it == use.values.end() || component >= it->second.size()) return std::nullopt;
  return it->second[component];
}

// Fills the records `out` (sampled over the full probe's own domain) with the pruned probe's
// records `in`, column by name, so both shade the same points. A column only the full probe has
// is an input the pruned one never reads (a folded feature's roughness, the geometric normal's
// tilt a clear coat uses): it takes the use's value when the scene states one, else keeps its
// sample (the scene lets it take any value of its range; a neutral fold holds for all of them).
void mapRecords(const ProbeLayout& from, const ProbeLayout& to, const std::vector<float>& in, std::vector<float>& out,
                uint64_t count, const MaterialUse& use) {
  auto fromCols = from.columns(), toCols = to.columns();
  for (size_t k = 0; k < toCols.size(); ++k) {
    auto it = std::find(fromCols.begin(), fromCols.end(), toCols[k]);
    std::optional<double> v = useValue(use, toCols[k]);
    for (uint64_t r = 0; r < count; ++r) {
      float& dst = out[r * to.inStride + k];
      if (it != fromCols.end())
        dst = in[r * from.inStride + (it - fromCols.begin())];
      else if (v)
        dst = static_cast<float>(*v);
    }
  }
}

PairStats comparePrunedFull(harness::VulkanHarness& gpu, const ShaderLibrary& lib, const Permutation& pruned,
                            const Permutation& full, const MaterialUse& use, uint64_t seed) {
  ProbeProgram p = buildPermutationProbe(lib, pruned), f = buildPermutationProbe(lib, full);
  const ProbeLayout &lp = p.shader.layout, &lf = f.shader.layout;
  REQUIRE(lp.output == lf.output);
  std::vector<float> inP = generateSamples(lp, p.domain, kRecords, seed);
  std::vector<float> inF = generateSamples(lf, f.domain, kRecords, seed + 1);
  mapRecords(lp, lf, inP, inF, kRecords, use);
  ProbeRun rp = runProbe(gpu, p, inP), rf = runProbe(gpu, f, inF);
  PairStats s;
  s.prunedValid = compare(rp, p).passed();
  s.fullValid = compare(rf, f).passed();
  s.prunedInstructions = spirvInstructionCount(p.compiled.spirv);
  s.fullInstructions = spirvInstructionCount(f.compiled.spirv);
  const int n = componentCount(lp.output);  // the result; fed outputs (if any) are not shading
  for (uint64_t r = 0; r < kRecords; ++r)
    for (int c = 0; c < n; ++c) {
      size_t ip = r * lp.outStride + c, jf = r * lf.outStride + c;
      double gp = rp.gpu[ip], gf = rf.gpu[jf], refP = rp.reference[ip], refF = rf.reference[jf];
      double scale = std::max(std::abs(refF), kRelativeErrorFloor);
      double diff = std::abs(gp - gf);
      double allowed =
          allowance(p.tolerance, refP, rp.conditioning[ip]) + allowance(f.tolerance, refF, rf.conditioning[jf]);
      double refRel = std::abs(refP - refF) / scale;
      ++s.values;
      if (!(diff <= allowed)) ++s.failures;  // NaN counts as a failure
      if (!(refRel <= kReferenceRel)) ++s.referenceMismatch;
      s.maxAbs = std::max(s.maxAbs, diff);
      s.maxRel = std::max(s.maxRel, diff / scale);
      s.maxRefRel = std::max(s.maxRefRel, refRel);
      s.worstRatio = std::max(s.worstRatio, diff / allowed);
    }
  return s;
}

// The full form of a required permutation: the loaded material at the same quality, every
// feature on at the use's values, nothing folded.
Permutation fullOf(const Permutation& pruned, const MaterialDesc& fullMaterial) {
  Permutation f = pruned;
  f.material = &fullMaterial;
  f.folded.clear();
  return f;
}

bool isPruned(const Permutation& perm, const ShaderLibrary& lib) {
  const ShadingModel* model = lib.findModel(perm.material->model);
  return !perm.folded.empty() || perm.material->features.size() < model->features.size();
}

// Checks every pruned permutation (at fp32) of the scene against its full form, once per use of
// its material. Returns how many pairs were compared.
size_t checkScene(harness::VulkanHarness& gpu, const ShaderLibrary& lib, const SceneDesc& scene) {
  ScenePlan plan = planScene(scene, lib);
  size_t pairs = 0;
  uint64_t seed = 1;
  std::set<std::string> seen;
  for (Permutation perm : plan.required) {
    // fp16 permutations have no fp32 error bound to judge by (fp16Tolerance() only rejects
    // NaN/Inf): their quality selection and folding, which do not depend on the precision,
    // are checked at fp32.
    perm.precision = Precision::Fp32;
    if (!isPruned(perm, lib) || !seen.insert(perm.key()).second) continue;
    auto sm = std::find_if(scene.materials.begin(), scene.materials.end(),
                           [&](const SceneMaterial& m) { return m.material.name == perm.material->name; });
    REQUIRE(sm != scene.materials.end());
    for (const auto& use : sm->uses) {
      MaterialDesc fullMaterial = featureComplete(applyQuality(sm->material, perm.quality, lib), use, lib);
      PairStats s = comparePrunedFull(gpu, lib, perm, fullOf(perm, fullMaterial), use, seed);
      seed += 2;  // the full probe samples its own columns with seed + 1
      INFO(scene.name << ": " << perm.key() << " vs its feature-complete form: " << s.values << " values, max abs "
                      << s.maxAbs << ", max rel " << s.maxRel << ", worst diff/allowance " << s.worstRatio
                      << ", max reference rel " << s.maxRefRel << ", SPIR-V instructions " << s.prunedInstructions
                      << " vs " << s.fullInstructions);
      CHECK(s.prunedValid);
      CHECK(s.fullValid);
      CHECK(s.failures == 0);
      CHECK(s.referenceMismatch == 0);
      // Deterministic: a pruned shader is strictly smaller than the feature-complete one.
      CHECK(s.prunedInstructions < s.fullInstructions);
      WARN(perm.key() << ": max |pruned - full| " << s.maxAbs << " (rel " << s.maxRel << "), worst/allowance "
                      << s.worstRatio << ", SPIR-V " << s.prunedInstructions << " vs " << s.fullInstructions);
      ++pairs;
    }
  }
  return pairs;
}

}  // namespace

TEST_CASE("pruned permutations of a constructed scene equal their feature-complete forms", "[pruned][vulkan]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  // Three ways to be pruned: a feature folded (clear coat 0 in every use), a sheen folded
  // (sheenColor 0), and a material that never had the other features.
  SceneDesc scene;
  scene.name = "constructed";
  scene.file = "constructed.scene.json";
  scene.lights = {{LightType::Dir, "sun", {}}, {LightType::Point, "lamp", {}}};
  scene.materials.push_back({test::shippedMaterial("clearcoat_metal"), {test::useWith({{"clearCoat", {0.0}}})}, {}});
  scene.materials.push_back(
      {test::shippedMaterial("satin_sheen"), {test::useWith({{"sheenColor", {0.0, 0.0, 0.0}}})}, {}});
  scene.materials.push_back({test::shippedMaterial("filament_plastic"), {MaterialUse{}}, {}});
  size_t pairs = checkScene(gpu, lib, scene);
  CHECK(pairs == 3);
}

TEST_CASE("pruned permutations of the shipped example scenes equal their feature-complete forms", "[pruned][vulkan]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(test::sourceDir() / "examples/scenes"))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  REQUIRE(!files.empty());
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  size_t pairs = 0;
  for (const auto& f : files) pairs += checkScene(gpu, lib, loadScene(f.string(), lib));
  CHECK(pairs > 0);  // the shipped scenes exist to show pruning: at least one pair
}

TEST_CASE("a fold that is not neutral in the full form is caught", "[pruned][vulkan]") {
  // Negative control: clear coat folded from the pruned shader, but 0.5 in the full one.
  const ShaderLibrary& lib = test::shippedLibrary();
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  MaterialDesc loaded = test::shippedMaterial("clearcoat_metal");
  MaterialDesc pruned = foldFeatures(loaded, {"clearcoat"}, lib);
  MaterialUse use = test::useWith({{"clearCoat", {0.5}}});
  MaterialDesc full = featureComplete(loaded, use, lib);
  Permutation p;
  p.material = &pruned;
  p.folded = {"clearcoat"};
  PairStats s = comparePrunedFull(gpu, lib, p, fullOf(p, full), use, 7);
  INFO("max |pruned - full| " << s.maxAbs << ", worst diff/allowance " << s.worstRatio);
  CHECK(s.failures > s.values / 2);
  CHECK(s.referenceMismatch > s.values / 2);
}
