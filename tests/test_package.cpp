// The engine-ready package (docs/package.md): manifest, deduplicated files per target, the
// self-contained GLSL include, the C++ header and its std140 asserts, the depfile, and the
// Engine kernel that all of them describe.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "support/build_paths.hpp"
#include "compile/glsl_compiler.hpp"
#include "emit/emitter.hpp"
#include "emit/fp16_rewrite.hpp"
#include "load/material_desc.hpp"
#include "permute/permutation.hpp"
#include "support/cli_support.hpp"
#include "support/pipeline_support.hpp"
#include "write/package_writer.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

fs::path tempDir(const std::string& name) { return test::freshTempDir("package", name); }

std::string material(const std::string& file) { return test::materialPath(file); }

nlohmann::json compilePackage(const std::string& args, const fs::path& out) {
  auto r = test::runCli("compile -q --no-cache " + args + " -o " + out.string());
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  return nlohmann::json::parse(test::readFile(out / "manifest.json"));
}

// Every regular file under `dir`, relative, with its bytes.
std::map<std::string, std::string> packageFiles(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).generic_string()] = test::readFile(e.path());
  return files;
}

// ue4_metal under another name: a different key, the same SPIR-V.
fs::path writeTwin(const fs::path& dir) {
  auto j = nlohmann::json::parse(test::readFile(material("ue4_metal.json")));
  j["name"] = "ue4_metal_twin";
  fs::path twin = dir / "ue4_metal_twin.json";
  std::ofstream(twin) << j.dump(2);
  return twin;
}

std::string shaderTypeOf(const std::string& valueType) {
  return valueType == "float" ? "float" : valueType == "vec2" ? "vec2" : "vec3";
}

// A compute shader that only uses the include: the engine's hooks, then the entry points.
// Every value comes from the buffer, as in an engine: with compile-time constant inputs
// spirv-opt (SPIRV-Tools v2023.1) folds the fp16 arithmetic into an invalid 16-bit
// OpConstant, which our spirv-val after spirv-opt rejects (docs/package.md).
std::string engineShader(const nlohmann::json& perm, const std::string& include, bool withHooks = true) {
  const bool fp16 = perm["precision"] == "fp16";
  std::string s = "#version 450\n";
  if (fp16) s += "#extension GL_EXT_shader_explicit_arithmetic_types_float16 : require\n";
  s += "layout(local_size_x = 1) in;\n";
  s += "layout(std430, binding = 0) buffer Io { float io[]; };\n";
  s += include;
  std::string body;
  if (withHooks && perm["needs_fetch_hooks"].get<bool>())
    body +=
        "vec3 mb_fetch_prefiltered(vec3 r, float lod) { return vec3(io[4]) + r * lod; }\n"
        "vec3 mb_fetch_dfg(float NoV, float perceptualRoughness) { return vec3(io[5], io[6], NoV * perceptualRoughness); }\n";
  std::string args;
  for (const auto& p : perm["parameters"])
    if (!p["constant"].get<bool>()) args += std::string(args.empty() ? "" : ", ") + shaderTypeOf(p["type"]) + "(io[3])";
  body +=
      "void main() {\n"
      "    ShadingFrame f;\n"
      "    f.n = normalize(vec3(io[0], io[1], io[2]));\n"
      "    f.v = normalize(vec3(io[1], io[0], io[2]));\n"
      "    f.ng = f.n;\n"
      "    f.t = normalize(vec3(io[2], 0.0, -io[0]));\n"
      "    ShadingPixel px = preparePixel(materialInputs(" +
      args +
      "), f);\n"
      "    vec3 r = emittedRadiance(px);\n";
  std::set<std::string> lights;
  for (const auto& l : perm["lights"]) lights.insert(l.get<std::string>());
  if (lights.count("dir"))
    body +=
        "    r += shadeDirectionalLight(px, f, DirectionalLight(normalize(vec3(io[7], io[8], 1.0)), vec3(io[9])));\n";
  if (lights.count("point")) body += "    PointLight pl;\n    r += shadePointLight(px, f, pl);\n";
  if (lights.count("spot")) body += "    SpotLight sl;\n    r += shadeSpotLight(px, f, sl);\n";
  if (perm["environment"] != "none") body += "    Environment env;\n    r += shadeEnvironment(px, f, env);\n";
  body += "    io[10] = float(r.x + r.y + r.z);\n}\n";
  // The engine writes fp32 GLSL; at fp16 the include's types are half (emit/precision.hpp).
  return s + (fp16 ? rewriteToFp16(body) : body);
}

}  // namespace

TEST_CASE("package manifest: keys, hashes, deduplicated files per target, deterministic", "[package]") {
  fs::path dir = tempDir("manifest");
  const std::string inputs = material("ue4_metal.json") + " " + writeTwin(dir).string() + " " +
                             material("filament_plastic.json") + " --targets spirv,glsl450";
  auto manifest = compilePackage("-j1 " + inputs, dir / "a");
  compilePackage("-j2 " + inputs, dir / "b");
  // Byte-identical at every -j and across runs: no time stamps, sorted keys.
  const auto files = packageFiles(dir / "a");
  CHECK(files == packageFiles(dir / "b"));

  REQUIRE(manifest["permutations"].size() == 3);
  CHECK(manifest["targets"] == nlohmann::json::array({"spirv", "glsl450"}));
  std::map<std::string, nlohmann::json> byMaterial;
  std::set<std::string> hashes, keys;
  for (const auto& p : manifest["permutations"]) {
    byMaterial[p["material"]] = p;
    keys.insert(p["key"].get<std::string>());
    hashes.insert(p["spirv_hash_xxh64"].get<std::string>());
    const std::string spv = files.at(p["files"]["spirv"].get<std::string>());
    CHECK(contentHash(spv.data(), spv.size()) == p["spirv_hash_xxh64"]);
    std::vector<uint32_t> words(spv.size() / 4);
    std::memcpy(words.data(), spv.data(), words.size() * 4);
    CHECK(spirvInstructionCount(words) == p["spirv_instructions"].get<size_t>());
    CHECK(files.count(p["files"]["glsl450"].get<std::string>()) == 1);
    CHECK(files.count(p["include"].get<std::string>()) == 1);
    // The Engine records hold no material parameter; those are the std140 block's members,
    // in the material's order, as SPIRV-Cross reflects them.
    std::vector<std::string> params, members, inputs;
    for (const auto& prm : p["parameters"])
      if (!prm["constant"].get<bool>()) params.push_back(prm["name"]);
    for (const auto& in : p["record_layout"]["inputs"]) inputs.push_back(in["name"]);
    REQUIRE(inputs.size() >= 3);
    CHECK(std::vector<std::string>(inputs.begin(), inputs.begin() + 3) == std::vector<std::string>{"n", "v", "l"});
    for (const auto& prm : params) CHECK(std::find(inputs.begin(), inputs.end(), prm) == inputs.end());
    for (const auto& u : p["reflection"]["uniform_buffers"])
      if (u["binding"] == 2)
        for (const auto& m : u["members"]) members.push_back(m["name"]);
    CHECK(members == params);
    CHECK(!params.empty());
  }
  // The twin differs from ue4_metal only in its name: two keys, one SPIR-V file per target.
  CHECK(keys.size() == 3);
  CHECK(hashes.size() == 2);
  CHECK(byMaterial["ue4_metal"]["files"] == byMaterial["ue4_metal_twin"]["files"]);
  CHECK(byMaterial["ue4_metal"]["include"] != byMaterial["ue4_metal_twin"]["include"]);
  size_t spirvFiles = 0, glslFiles = 0;
  for (const auto& [path, bytes] : files) {
    spirvFiles += path.rfind("spirv/", 0) == 0;
    glslFiles += path.rfind("glsl450/", 0) == 0;
  }
  CHECK(spirvFiles == 2);
  CHECK(glslFiles == 2);
  fs::remove_all(dir);
}

TEST_CASE("package manifest: each permutation says how its lights are shaded", "[package]") {
  // The standard model's sphere light by LTC at high quality and by the representative point at
  // low (models.md "Light methods"), with the roles and the LTC table hooks that follow; a
  // directional light has no methods.
  const fs::path dir = tempDir("light-methods");
  for (const char* quality : {"high", "low"}) {
    const nlohmann::json m =
        compilePackage(material("filament_plastic.json") + " --lights dir,sphere --quality " + quality, dir / quality);
    REQUIRE(m["permutations"].size() == 1);
    const nlohmann::json& p = m["permutations"][0];
    const bool ltc = std::string(quality) == "high";
    CHECK(p["light_methods"] == nlohmann::json{{"sphere", ltc ? "ltc" : "representative_point"}});
    CHECK(p["bricks"].contains("sphere_light_ltc_cv") == ltc);
    CHECK(p["bricks"].contains("sphere_light_point"));
    const std::string include = test::readFile(dir / quality / p["include"].get<std::string>());
    CHECK((include.find("#define MB_LTC_TABLE 1") != std::string::npos) == ltc);
    CHECK((include.find("//   vec4 mb_fetch_ltc_matrix(float NoV") != std::string::npos) == ltc);  // the hooks it needs
  }
  fs::remove_all(dir);
}

TEST_CASE("each include is self-contained: hooks + include + calls compile", "[package]") {
  fs::path dir = tempDir("include");
  const std::string mats =
      material("velvet_green.json") + " " + material("worn_car_paint.json") + " " + material("brushed_metal.json");
  auto ibl = compilePackage(mats + " --lights dir,point,spot --environment ibl_lut", dir / "ibl");
  auto half = compilePackage(material("filament_plastic.json") + " --precision fp16", dir / "half");
  size_t checked = 0;
  for (const auto& [pkg, manifest] : {std::pair{dir / "ibl", ibl}, std::pair{dir / "half", half}})
    for (const auto& p : manifest["permutations"]) {
      const std::string include = test::readFile(pkg / p["include"].get<std::string>());
      INFO(p["key"]);
      CHECK(include.find("\n#line") == std::string::npos);
      CHECK(include.find("\n#version") == std::string::npos);
      CHECK(include.find("\n#extension") == std::string::npos);
      CHECK(include.find("MB_NO_PROBE") == std::string::npos);
      CHECK(include.find("// from shaderlib/") != std::string::npos);
      const bool ibl = p["environment"] == "ibl_lut";
      CHECK(ibl == p["needs_fetch_hooks"].get<bool>());
      const std::string name = p["key"].get<std::string>() + ".engine.comp";
      CHECK_NOTHROW(compileComputeGlsl(engineShader(p, include), name));
      // The hooks really are the engine's to define: without them an IBL shader does not link.
      if (ibl)
        CHECK_THROWS_WITH(compileComputeGlsl(engineShader(p, include, false), name), Catch::Contains("mb_fetch_"));
      ++checked;
    }
  CHECK(checked == 4);
  fs::remove_all(dir);
}

TEST_CASE("the C++ header compiles, finds every key, and its std140 asserts can fail", "[package]") {
  fs::path dir = tempDir("header");
  auto manifest = compilePackage(
      material("worn_car_paint.json") + " " + material("ue4_metal.json") + " --namespace test_pkg --header pkg.hpp",
      dir / "pkg");
  std::string tu = "#include \"pkg.hpp\"\n";
  for (const auto& p : manifest["permutations"])
    tu += "static_assert(test_pkg::findPermutation(\"" + p["key"].get<std::string>() + "\") != nullptr);\n";
  tu += "static_assert(!test_pkg::hasPermutation(\"no.such.key\"));\n";
  tu += "static_assert(test_pkg::kPermutationCount == " + std::to_string(manifest["permutations"].size()) + ");\n";
  tu += "static_assert(test_pkg::recordOffset(test_pkg::kPermutations[0], \"v\") == 3);\n";
  tu += "int main() { return 0; }\n";
  std::ofstream(dir / "pkg" / "use.cpp") << tu;
  auto compile = [&](const std::string& file) {
    return std::system(("cd " + (dir / "pkg").string() + " && " + test::cxxCompiler() +
                        " -std=c++17 -Wall -Wextra -Werror "
                        "-fsyntax-only " +
                        file + " > compile.log 2>&1")
                           .c_str());
  };
  const int clean = compile("use.cpp");
  INFO(test::readFile(dir / "pkg" / "compile.log"));
  CHECK(clean == 0);

  // The asserts are not decorative: shift one reflected offset and the header must not compile.
  std::string header = test::readFile(dir / "pkg" / "pkg.hpp");
  const size_t at = header.find(") == ", header.find("static_assert(offsetof("));
  REQUIRE(at != std::string::npos);
  const size_t end = header.find(',', at);
  const int offset = std::stoi(header.substr(at + 5, end - at - 5));
  header.replace(at + 5, end - at - 5, std::to_string(offset + 4));
  std::ofstream(dir / "pkg" / "pkg.hpp", std::ios::trunc) << header;
  CHECK(compile("use.cpp") != 0);
  CHECK_THAT(test::readFile(dir / "pkg" / "compile.log"), Catch::Contains("std140 offset of"));
  fs::remove_all(dir);
}

TEST_CASE("compile --depfile lists the material, model and included shader library files", "[package]") {
  fs::path dir = tempDir("depfile");
  auto r = test::runCli("compile -q --no-cache " + material("velvet_green.json") + " -o " + (dir / "pkg").string() +
                        " --depfile " + (dir / "pkg.d").string());
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  const std::string dep = test::readFile(dir / "pkg.d");
  const std::string lib = fs::absolute(ShaderLibrary::defaultRoot()).lexically_normal().generic_string();
  CHECK(dep.rfind(fs::absolute(dir / "pkg" / "manifest.json").lexically_normal().generic_string() + ":", 0) == 0);
  CHECK_THAT(dep, Catch::Contains(fs::absolute(material("velvet_green.json")).lexically_normal().generic_string()));
  CHECK_THAT(dep, Catch::Contains(lib + "/manifest.json"));
  CHECK_THAT(dep, Catch::Contains(lib + "/models/cloth.json"));
  CHECK_THAT(dep, Catch::Contains(lib + "/common/lights.glsl"));
  // Every listed file exists (a missing one would make the build rerun forever).
  size_t listed = 0;
  std::istringstream in(dep.substr(dep.find(':') + 1));
  for (std::string word; in >> word;)
    if (word != "\\") {
      INFO(word);
      CHECK(fs::exists(word));
      ++listed;
    }
  CHECK(listed > 5);
  CHECK(test::runCli("compile " + material("velvet_green.json") + " --explain --depfile x.d").exitCode == 2);
  fs::remove_all(dir);
}

TEST_CASE("compile --depfile lists the files a macro-form material #includes, nested ones too", "[package]") {
  fs::path dir = tempDir("depfile_include");
  fs::create_directories(dir / "shared");
  std::ofstream(dir / "m.mat") << "#define MATERIAL included_plastic\n#define MODEL standard\n"
                                  "#include \"shared/bricks.mat\"\n#define PARAM_roughness 0.5\n";
  std::ofstream(dir / "shared" / "bricks.mat")
      << "#define BRICK_roughness roughness_clamped\n#define BRICK_diffuse diffuse_lambert\n"
         "#define BRICK_specular_d d_ggx\n#define BRICK_specular_v v_smith_ggx_correlated\n#include \"fresnel.mat\"\n";
  std::ofstream(dir / "shared" / "fresnel.mat") << "#define BRICK_fresnel f_schlick\n";
  auto r = test::runCli("compile -q --no-cache " + (dir / "m.mat").string() + " -o " + (dir / "pkg").string() +
                        " --depfile " + (dir / "pkg.d").string());
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  const std::string dep = test::readFile(dir / "pkg.d");
  for (const fs::path& f : {dir / "m.mat", dir / "shared" / "bricks.mat", dir / "shared" / "fresnel.mat"})
    CHECK_THAT(dep, Catch::Contains(fs::absolute(f).lexically_normal().generic_string()));
  fs::remove_all(dir);
}

TEST_CASE("Engine mode moves the material parameters to a std140 block; Probe mode keeps them", "[package]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  MaterialDesc m = loadMaterialJson(material("worn_car_paint.json"), lib);
  Permutation perm;
  perm.material = &m;
  EmittedShader probe = emitPermutation(lib, perm, false, EmitMode::Probe);
  EmittedShader engine = emitPermutation(lib, perm, false, EmitMode::Engine);
  CHECK(probe.glsl.find("MaterialParamsBlock") == std::string::npos);
  CHECK(engine.glsl.find("layout(std140, set = 0, binding = 2) uniform MaterialParamsBlock {") != std::string::npos);
  std::vector<std::string> params;
  for (const auto& p : m.params)
    if (!p.constant) params.push_back(p.name);
  REQUIRE(!params.empty());
  // The Engine record is the probe record without the parameters, re-packed in order.
  std::vector<std::string> expected;
  for (const auto& in : probe.layout.inputs)
    if (std::find(params.begin(), params.end(), in.name) == params.end()) expected.push_back(in.name);
  std::vector<std::string> got;
  uint32_t offset = 0;
  for (const auto& in : engine.layout.inputs) {
    got.push_back(in.name);
    CHECK(in.offset == offset);
    offset += static_cast<uint32_t>(componentCount(in.type));
  }
  CHECK(got == expected);
  CHECK(engine.layout.inStride == offset);
  CHECK(engine.layout.outStride == 3);
  for (const auto& p : params) CHECK(engine.glsl.find("p_" + p + " = mbParams." + p + ";") != std::string::npos);
  CHECK_NOTHROW(compileComputeGlsl(engine.glsl, engine.fileName));
}

TEST_CASE("a scene package records the scene's counts and every target's files", "[package]") {
  fs::path dir = tempDir("scene");
  const std::string scene = (test::sourceDir() / "examples/scenes/gallery.json").string();
  auto manifest = compilePackage("--scene " + scene + " --targets spirv,glsl450,essl310,hlsl,msl", dir / "pkg");
  REQUIRE(manifest.contains("scene"));
  CHECK(manifest["scene"]["file"] == scene);
  CHECK(manifest["scene"]["possible"].get<size_t>() > manifest["permutations"].size());
  CHECK(manifest["counts"]["required"] == manifest["permutations"].size());
  CHECK(manifest["targets"] == nlohmann::json::array({"spirv", "glsl450", "essl310", "hlsl", "msl"}));
  const std::string header = test::readFile(dir / "pkg" / "matbricks_materials.hpp");
  std::vector<std::string> keys;
  for (const auto& p : manifest["permutations"]) {
    keys.push_back(p["key"]);
    INFO(p["key"]);
    CHECK(p["files"].size() == 5);
    for (const auto& [target, file] : p["files"].items()) CHECK(fs::exists(dir / "pkg" / file.get<std::string>()));
    CHECK(header.find("{\"" + p["key"].get<std::string>() + "\", ") != std::string::npos);
  }
  // The header's table, like the plan, is sorted by key (findPermutation is a linear scan,
  // but engines diffing two headers see stable order).
  CHECK(std::is_sorted(keys.begin(), keys.end()));
  fs::remove_all(dir);
}
