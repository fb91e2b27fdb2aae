// Shared by the shading-model tests: validates one permutation of an inline JSON material
// on lavapipe (the same probe, reference and tolerance as `matbricks validate`).
#pragma once
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "harness_support.hpp"
#include "pipeline_support.hpp"
#include "validate/validation.hpp"

namespace mb::test {

// 4096 samples: a few seconds per permutation on lavapipe.
inline void requireModelPermutationValidates(harness::VulkanHarness& gpu, const MaterialDesc& material,
                                             const std::vector<std::string>& lights, EnvironmentMode environment,
                                             uint64_t seed = 5) {
  Permutation perm;
  perm.material = &material;
  perm.lights = canonicalLights(parseLightTypes(lights));
  perm.environment = environment;
  ValidationRecord r = validateProbe(gpu, buildPermutationProbe(shippedLibrary(), perm), "permutation", 4096, seed);
  INFO(r.key << ": max_abs " << r.stats.maxAbs << " max_rel " << r.stats.maxRel << " failures " << r.stats.failures
             << " worst " << r.worstInput);
  CHECK(r.stats.nanCount == 0);
  CHECK(r.stats.infCount == 0);
  CHECK(r.stats.referenceInvalid == 0);
  CHECK(r.passed());
}

inline void requireNoValidationLayerMessages(const harness::VulkanHarness& gpu) {
  auto msgs = gpu.validationMessages();
  for (const auto& m : msgs) UNSCOPED_INFO("validation layer: " << m);
  REQUIRE(msgs.empty());
}

}  // namespace mb::test
