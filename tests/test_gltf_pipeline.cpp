// glTF materials through the rest of the pipeline: the generated surface code and every
// permutation compile, and the materials whose inputs are all constants validate against
// the model's double reference on lavapipe like any other material.
#include <catch2/catch.hpp>

#include "compile/glsl_compiler.hpp"
#include "emit/emitter.hpp"
#include "load/gltf_import.hpp"
#include "permute/permutation.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"
#include "validate/validation.hpp"

using namespace mb;

namespace {

std::vector<MaterialDesc> exampleGltfMaterials() {
  std::vector<MaterialDesc> out;
  for (const char* file : {"textured_props.gltf", "showroom.glb", "unsupported_used.gltf"})
    for (auto& m :
         importGltfMaterials((test::sourceDir() / "examples" / "gltf" / file).string(), test::shippedLibrary()))
      out.push_back(std::move(m));
  return out;
}

}  // namespace

// The default permutation (directional light, no environment) per material: the generated
// surface code and the features do not depend on the light and environment axes, which the
// model's own tests cover (every light type and environment costs ~0.35 s of compile here).
TEST_CASE("every glTF example material emits and compiles", "[gltf][pipeline]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  std::vector<MaterialDesc> materials = exampleGltfMaterials();
  REQUIRE(materials.size() == 10);
  std::vector<Permutation> perms = permutationsFor(materials);
  REQUIRE(perms.size() == materials.size());
  for (const auto& perm : perms) {
    EmittedShader shader = emitPermutation(lib, perm);
    INFO(shader.key);
    CompileResult r;
    REQUIRE_NOTHROW(r = compileComputeGlsl(shader.glsl, shader.fileName));
    CHECK_FALSE(r.spirv.empty());
  }
}

// Texture inputs go through generated surface code, which the C++ reference composition does
// not run; materials with only constants have nothing the reference does not see.
TEST_CASE("glTF example materials without textures validate on lavapipe", "[gltf][pipeline][vulkan]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  std::vector<MaterialDesc> constantOnly;
  for (auto& m : exampleGltfMaterials())
    if (!m.surface.present()) constantOnly.push_back(std::move(m));
  REQUIRE(constantOnly.size() == 7);
  for (const auto& perm : permutationsFor(constantOnly)) {
    ValidationRecord r = validateProbe(gpu, buildPermutationProbe(lib, perm), "permutation", 4096, 11);
    INFO(r.key << ": max_abs " << r.stats.maxAbs << " max_rel " << r.stats.maxRel << " worst " << r.worstInput);
    CHECK(r.stats.nanCount == 0);
    CHECK(r.stats.infCount == 0);
    CHECK(r.passed());
  }
  auto msgs = gpu.validationMessages();
  for (const auto& msg : msgs) UNSCOPED_INFO("validation layer: " << msg);
  CHECK(msgs.empty());
}
