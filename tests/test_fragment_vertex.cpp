// The reference vertex shader (shaderlib/common/engine_vertex.vert, docs/fragment-stage.md)
// compiles for Vulkan, passes spirv-val, and writes exactly the attributes the fragment stage
// reads: the same locations, names and types as the documented interface and as a real
// permutation's fragment shader that reads all four.
#include <catch2/catch.hpp>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/libspirv.h>

#include "compile/glsl_compiler.hpp"
#include "compile/targets.hpp"
#include "emit/fragment_shader.hpp"
#include "load/gltf_import.hpp"
#include "support/pipeline_support.hpp"

using namespace mb;

namespace {

std::vector<uint32_t> compileVertex(const std::string& source) {
  ensureGlslangInitialized();
  glslang::TShader shader(EShLangVertex);
  const char* text = source.c_str();
  shader.setStrings(&text, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, EShLangVertex, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  INFO(shader.getInfoLog());
  REQUIRE(shader.parse(GetDefaultResources(), 450, false, messages));
  glslang::TProgram program;
  program.addShader(&shader);
  REQUIRE(program.link(messages));
  std::vector<uint32_t> spirv;
  glslang::GlslangToSpv(*program.getIntermediate(EShLangVertex), spirv);
  return spirv;
}

}  // namespace

TEST_CASE("the reference vertex shader writes exactly the fragment stage's attributes", "[fragment]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  const std::vector<uint32_t> vertex = compileVertex(lib.source("common/engine_vertex.vert"));
  CHECK(spirvValidationErrors(vertex, SPV_ENV_VULKAN_1_1).empty());
  const nlohmann::json outputs = reflectSpirv(vertex).at("stage_outputs");
  CHECK(outputs == nlohmann::json::parse(R"([
      {"location": 0, "name": "mbWorldPosition", "type": "vec3"},
      {"location": 1, "name": "mbWorldNormal", "type": "vec3"},
      {"location": 2, "name": "mbWorldTangent", "type": "vec4"},
      {"location": 3, "name": "mbUv0", "type": "vec2"}])"));

  // A normal-mapped, textured glTF material reads all four, even after spirv-opt.
  const auto mats = importGltfMaterials((test::sourceDir() / "examples/gltf/textured_props.gltf").string(), lib);
  Permutation perm = validationPermutationsFor(mats.at(0), lib).at(0);
  const EmittedShader fragment = emitFragmentShader(lib, perm);
  CompileOptions o;
  o.stage = ShaderStage::Fragment;
  CHECK(reflectSpirv(compileComputeGlsl(fragment.glsl, fragment.fileName, o).spirv).at("stage_inputs") == outputs);
}
