// The HLSL and MSL engine includes (compile/engine_includes.hpp, docs/package.md "HLSL and
// MSL includes"): for every shipped material (materials/*.json and the glTF examples' materials),
// every light type and environment mode its model shades, at fp32 and fp16, each include is
// wrapped in a minimal shader of its language that defines the hooks and calls every contract
// function: HLSL through glslang's HLSL front end as a pixel shader, MSL by the structural check.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <thread>

#include "compile/engine_includes.hpp"
#include "compile/target_checks.hpp"
#include "emit/emitter.hpp"
#include "permute/permutation.hpp"
#include "support/pipeline_support.hpp"

using namespace mb;

namespace {

std::vector<MaterialDesc> shippedMaterials() {
  std::vector<std::string> files = test::exampleMaterialFiles();
  for (const char* gltf : {"examples/gltf/showroom.gltf", "examples/gltf/textured_props.gltf"})
    files.push_back((test::sourceDir() / gltf).string());
  std::vector<MaterialDesc> out;
  for (const auto& f : files)
    for (auto& m : loadMaterialFile(f, test::shippedLibrary())) out.push_back(std::move(m));
  return out;
}

struct Checked {
  std::string key, glsl;
  std::map<std::string, std::string> includes;
  std::string error;
};

// Each permutation's includes, made on two threads (the build's code path, checks included).
std::vector<Checked> buildAll(const std::vector<Permutation>& perms) {
  std::vector<Checked> out(perms.size());
  for (size_t i = 0; i < perms.size(); ++i) {
    EmittedShader s = emitPermutation(test::shippedLibrary(), perms[i], false, EmitMode::Engine);
    out[i].key = s.key;
    out[i].glsl = s.glsl;
  }
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i; (i = next++) < out.size();) {
      try {
        out[i].includes = crossCompileIncludes(out[i].glsl, {Target::Hlsl, Target::Msl}, out[i].key);
      } catch (const std::exception& e) {
        out[i].error = e.what();
      }
    }
  };
  std::thread other(worker);
  worker();
  other.join();
  return out;
}

std::vector<std::string> definedContract(const std::string& code) {
  std::vector<std::string> names;
  for (const auto& f : contractFunctions(code)) names.push_back(f.name);
  return names;
}

}  // namespace

TEST_CASE("HLSL and MSL includes of every shipped material compile in their wrappers", "[includes][release-pass]") {
  const std::vector<MaterialDesc> materials = shippedMaterials();
  std::vector<Permutation> perms;
  for (const auto& m : materials)
    for (Permutation p : validationPermutationsFor(m, test::shippedLibrary()))
      for (Precision precision : allPrecisions()) {
        p.precision = precision;
        perms.push_back(p);
      }
  REQUIRE(perms.size() >= 60);
  size_t environments = 0;
  for (const auto& c : buildAll(perms)) {
    INFO(c.key);
    REQUIRE(c.error.empty());
    const std::string glsl = c.glsl.substr(0, c.glsl.find("#ifndef MB_NO_PROBE"));
    const std::vector<std::string> expected = definedContract(glsl);
    REQUIRE(expected.size() >= 4);
    for (const auto& [target, body] : c.includes) {
      INFO(target);
      // The same functions as the GLSL include, under the same names, and nothing of the shell.
      CHECK(definedContract(body) == expected);
      CHECK(body.find("main(") == std::string::npos);
      CHECK(body.find("gl_WorkGroupSize") == std::string::npos);
      // The hooks the environment and the lights call, and only those, are left to the engine:
      // the LTC table's two for rectangle and disk lights, and the sheen table's two more with a
      // sheen.
      const bool ltcLights = c.key.find("+rect") != std::string::npos || c.key.find("+disk") != std::string::npos ||
                             c.key.find(".rect") != std::string::npos || c.key.find(".disk") != std::string::npos;
      const bool sheen = glsl.find("#define MB_FEATURE_SHEEN") != std::string::npos;
      const size_t ltcHooks = ltcLights ? (sheen ? 4 : 2) : 0;
      const size_t hooks = ltcHooks + (c.key.find(".ibl_lut.") != std::string::npos        ? 2
                                       : c.key.find(".ibl_analytic.") != std::string::npos ? 1
                                                                                           : 0);
      CHECK(hookPrototypes(body).size() == hooks);
      CHECK(missingContractFunctions(glsl, body).empty());
      const bool msl = target == "msl";
      const std::string wrapper = includeWrapper(body, msl ? IncludeLanguage::Msl : IncludeLanguage::Hlsl);
      CHECK((msl ? checkMslInclude(wrapper) : checkHlsl(wrapper, true)) == "");
    }
    CHECK(c.includes.size() == 2);
    environments += c.key.find(".none.") == std::string::npos;
  }
  CHECK(environments > 0);
}

TEST_CASE("a contract function missing from an include is found", "[includes]") {
  Permutation p;
  const MaterialDesc m = test::shippedMaterial("ue4_metal");
  p.material = &m;
  p.lights = {LightType::Dir, LightType::Sphere};
  p.environment = EnvironmentMode::IblLut;
  const Checked c = buildAll({p}).front();
  REQUIRE(c.error.empty());
  const std::string glsl = c.glsl.substr(0, c.glsl.find("#ifndef MB_NO_PROBE"));
  for (const auto& [target, body] : c.includes) {
    INFO(target);
    CHECK(missingContractFunctions(glsl, body).empty());
    for (const char* name : {"shadeSphereLight", "materialInputs", "shadeEnvironment"}) {
      // The definition renamed away, as a lost function would be.
      std::string broken = body;
      const size_t at = broken.find(std::string(" ") + name + "(");
      REQUIRE(at != std::string::npos);
      broken.insert(at + 1, "lost_");
      CHECK(missingContractFunctions(glsl, broken) == std::vector<std::string>{name});
    }
  }
}
