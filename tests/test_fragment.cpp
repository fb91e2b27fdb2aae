// Issue 13, item 1: every permutation's fragment shader (docs/fragment-stage.md). For every
// shipped material (materials/*.json and the glTF examples), every light type and environment
// its model shades, at fp32 and fp16: the fragment shader compiles with glslang, passes
// spirv-val, and its SPIRV-Cross reflection is exactly the documented interface, with the
// frame block laid out identically in every permutation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <spirv-tools/libspirv.h>

#include "compile/glsl_compiler.hpp"
#include "compile/targets.hpp"
#include "emit/fragment_shader.hpp"
#include "emit/fragment_textures.hpp"
#include "load/gltf_import.hpp"
#include "support/pipeline_support.hpp"

using namespace mb;

namespace {

std::vector<MaterialDesc> shippedFragmentMaterials() {
  const ShaderLibrary& lib = test::shippedLibrary();
  std::vector<MaterialDesc> out;
  for (const auto& file : test::exampleMaterialFiles()) out.push_back(loadMaterialJson(file, lib));
  for (const char* gltf : {"showroom.gltf", "textured_props.gltf"})
    for (auto& m : importGltfMaterials((test::sourceDir() / "examples" / "gltf" / gltf).string(), lib))
      out.push_back(std::move(m));
  return out;
}

std::vector<Permutation> withPrecisions(const std::vector<Permutation>& perms) {
  std::vector<Permutation> out;
  for (const auto& p : perms)
    for (Precision precision : allPrecisions()) {
      Permutation q = p;
      q.precision = precision;
      out.push_back(q);
    }
  return out;
}

CompileOptions fragmentOptions(const Permutation& perm) {
  CompileOptions o;
  o.stage = ShaderStage::Fragment;
  o.optimization = perm.precision == Precision::Fp32
                       ? OptimizationLevel::O2
                       : OptimizationLevel::O0;  // as the package builds (build.cpp unitFor)
  return o;
}

const nlohmann::json* uniformAt(const nlohmann::json& reflection, int binding) {
  for (const auto& u : reflection.at("uniform_buffers"))
    if (u.at("set") == 0 && u.at("binding") == binding) return &u;
  return nullptr;
}

// MbFrameBlock's std140 layout (engine_frame.glsl; GLSL 4.50 spec 7.6.2.2): three vec4s, four
// 32-byte directional records, five arrays of four 64-byte local records, vec4 sh[9], a vec4,
// then (interface version 2) two arrays of four 64-byte area records.
const std::vector<std::pair<std::string, int>> kFrameMembers = {
    {"cameraPosition", 0}, {"lightCounts", 16},   {"lightCounts2", 32},  {"dirLights", 48},
    {"pointLights", 176},  {"spotLights", 432},   {"sphereLights", 688}, {"tubeLights", 944},
    {"sh", 1200},          {"environment", 1344}, {"rectLights", 1360},  {"diskLights", 1616}};
constexpr int kFrameSize = 1872;

}  // namespace

TEST_CASE("Every shipped permutation's fragment shader compiles, validates and reflects the documented interface",
          "[fragment][release-pass]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  const std::vector<MaterialDesc> materials = shippedFragmentMaterials();
  std::string frameLayout;  // the first permutation's MbFrameBlock reflection
  std::set<std::string> covered;
  size_t count = 0, textured = 0;
  for (const auto& mat : materials) {
    for (const auto& perm : withPrecisions(validationPermutationsFor(mat, lib))) {
      INFO(perm.key());
      const EmittedShader s = emitFragmentShader(lib, perm);
      CHECK(s.fileName == perm.key() + ".frag");
      const std::vector<uint32_t> spirv = compileComputeGlsl(s.glsl, s.fileName, fragmentOptions(perm)).spirv;
      CHECK(spirvValidationErrors(spirv, SPV_ENV_VULKAN_1_1).empty());
      const nlohmann::json r = reflectSpirv(spirv);
      ++count;
      covered.insert(environmentModeName(perm.environment) + "/" + precisionName(perm.precision));
      for (LightType l : perm.lights) covered.insert(lightTypeName(l));

      CHECK(r.at("entry_point") == "main");
      CHECK(r.at("stage") == "fragment");
      CHECK(r.at("storage_buffers").empty());
      CHECK(r.at("push_constants").empty());
      // Output: radiance at location 0.
      CHECK(r.at("stage_outputs") == nlohmann::json::parse(R"([{"name":"mbOutColor","location":0,"type":"vec4"}])"));
      // Inputs: the documented attributes; one the permutation does not read may be compiled
      // away (docs/fragment-stage.md), but position and normal are read by every one.
      const std::map<int, std::pair<std::string, std::string>> attributes = {{0, {"mbWorldPosition", "vec3"}},
                                                                             {1, {"mbWorldNormal", "vec3"}},
                                                                             {2, {"mbWorldTangent", "vec4"}},
                                                                             {3, {"mbUv0", "vec2"}}};
      std::set<int> locations;
      for (const auto& in : r.at("stage_inputs")) {
        const int loc = in.at("location");
        REQUIRE(attributes.count(loc));
        CHECK(in.at("name") == attributes.at(loc).first);
        CHECK(in.at("type") == attributes.at(loc).second);
        locations.insert(loc);
      }
      CHECK(locations.count(0));
      CHECK(locations.count(1));

      // The frame block: binding 1, the same layout in every permutation.
      const nlohmann::json* frame = uniformAt(r, 1);
      REQUIRE(frame);
      CHECK(frame->at("name") == "MbFrameBlock");
      CHECK(frame->at("size") == kFrameSize);
      REQUIRE(frame->at("members").size() == kFrameMembers.size());
      for (size_t i = 0; i < kFrameMembers.size(); ++i) {
        CHECK(frame->at("members")[i].at("name") == kFrameMembers[i].first);
        CHECK(frame->at("members")[i].at("offset") == kFrameMembers[i].second);
      }
      if (frameLayout.empty()) frameLayout = frame->dump();
      CHECK(frame->dump() == frameLayout);

      // The material parameters: binding 0, the compute kernel's members in its order.
      std::vector<std::string> params;
      for (const auto& p : perm.material->params)
        if (!p.constant) params.push_back(p.name);
      size_t blocks = 1;
      if (const nlohmann::json* block = uniformAt(r, 0)) {
        ++blocks;
        CHECK(block->at("name") == "MbMaterialParams");
        std::vector<std::string> members;
        for (const auto& m : block->at("members")) members.push_back(m.at("name"));
        CHECK(members == params);
      } else {
        // Only a material whose every run-time parameter is a texture input loses the block.
        const auto textures = fragmentTextures(*perm.material);
        for (const auto& p : params)
          CHECK(std::any_of(textures.begin(), textures.end(), [&](const FragmentTexture& t) { return t.param == p; }));
      }
      CHECK(r.at("uniform_buffers").size() == blocks);

      // Samplers: the environment's and one per texture record, nothing else.
      std::map<int, std::string> expected;
      const EnvironmentMode env = perm.environment;
      if (env == EnvironmentMode::IblLut || env == EnvironmentMode::IblAnalytic) expected[2] = "samplerCube";
      if (env == EnvironmentMode::IblLut) expected[3] = "sampler2D";
      if (perm.hasLight(LightType::Rect) || perm.hasLight(LightType::Disk)) expected[4] = "sampler2D";
      const auto textures = fragmentTextures(*perm.material);
      for (const auto& t : textures) expected[t.binding] = "sampler2D";
      textured += !textures.empty();
      std::map<int, std::string> got;
      for (const auto& si : r.at("sampled_images")) {
        CHECK(si.at("set") == 0);
        got[si.at("binding").get<int>()] = si.at("type");
      }
      // A texture input that cannot reach the output (an occlusion texture without an
      // environment) is compiled away with its sampler, as the kernel's block member is.
      for (const auto& [binding, type] : got) {
        INFO("binding " << binding);
        REQUIRE(expected.count(binding));
        CHECK(expected.at(binding) == type);
      }
      for (const auto& [binding, type] : expected)
        if (binding < kFirstTextureBinding) CHECK(got.count(binding));
    }
  }
  for (const char* c : {"dir", "point", "spot", "sphere", "tube", "rect", "disk", "none/fp32", "none/fp16",
                        "ibl_lut/fp32", "ibl_lut/fp16", "ibl_analytic/fp32", "ibl_analytic/fp16"})
    CHECK(covered.count(c));
  CHECK(textured > 0);
  CHECK(count >= 80);
}
