// Specialized permutations run on lavapipe against the double reference, through the same
// validation path as every example permutation (tests/test_pipeline.cpp): the reference
// follows MaterialDesc::bricks and ::params, so a quality level's bricks and a folded feature
// are checked with no extra code.
#include <catch2/catch.hpp>

#include "load/scene_desc.hpp"
#include "permute/scene_plan.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"
#include "validate/validation.hpp"

using namespace mb;

namespace {

const Permutation& requiredKey(const ScenePlan& plan, const std::string& key) {
  for (const auto& p : plan.required)
    if (p.key() == key) return p;
  FAIL("the plan has no permutation " << key);
  throw std::logic_error("unreachable");
}

void validates(harness::VulkanHarness& gpu, const Permutation& perm) {
  ValidationRecord r = validateProbe(gpu, buildPermutationProbe(test::shippedLibrary(), perm), "permutation", 1024, 3);
  INFO(r.key << ": max_rel " << r.stats.maxRel << " worst " << r.worstInput);
  CHECK(r.stats.nanCount == 0);
  CHECK(r.stats.infCount == 0);
  CHECK(r.passed());
}

}  // namespace

TEST_CASE("a low-quality and a folded scene permutation validate on lavapipe", "[scene][gpu][vulkan]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  // Low quality: sh_l1_irradiance and no energy compensation in place of the defaults. fp32,
  // so the reference's tolerance applies (the mobile scene itself ships fp16).
  SceneDesc mobile = loadScene((test::sourceDir() / "examples/scenes/mobile.json").string(), lib);
  mobile.precisions = {Precision::Fp32};
  mobile.environments = {EnvironmentMode::IblLut};
  ScenePlan low = planScene(mobile, lib);
  const Permutation& plastic = requiredKey(low, "filament_plastic.standard.dir+point.ibl_lut.fp32.low");
  CHECK(plastic.material->bricks.at("sh_irradiance") == "sh_l1_irradiance");
  CHECK(plastic.material->bricks.at("energy_compensation") == "energy_compensation_none");
  validates(gpu, plastic);
  // Folded: the clear coat of clearcoat_metal is gone (showroom uses it only at clearCoat 0).
  ScenePlan showroom = planScene(loadScene((test::sourceDir() / "examples/scenes/showroom.json").string(), lib), lib);
  const Permutation& folded =
      requiredKey(showroom, "clearcoat_metal.standard.dir+point+sphere.ibl_lut.fp32.without-clearcoat");
  CHECK(folded.material->features.empty());
  validates(gpu, folded);
  CHECK(gpu.validationMessages().empty());
}
