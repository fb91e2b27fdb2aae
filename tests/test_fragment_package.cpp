// Issue 13, item 1, in the package (docs/fragment-stage.md, docs/package.md "Fragment
// shaders"): `compile` writes every permutation's fragment shader in every requested target,
// describes it in manifest.json (files, hash, instruction count, reflection, textures), gives
// the C++ header MbFrameBlock and the bindings, and keeps the package deterministic across -j
// and stream windows; the fragment shader is cached with the kernel.
#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "support/build_paths.hpp"
#include "compile/build.hpp"
#include "compile/glsl_compiler.hpp"
#include "compile/targets.hpp"
#include "support/build_support.hpp"
#include "support/cli_support.hpp"
#include "support/pipeline_support.hpp"
#include "write/package_parts.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

const std::string kAllTargets = " --targets spirv,glsl450,essl310,hlsl,msl";

nlohmann::json compileTo(const std::string& args, const fs::path& out) {
  auto r = test::runCli("compile -q --no-cache " + args + " -o " + out.string());
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  return nlohmann::json::parse(test::readFile(out / "manifest.json"));
}

std::map<std::string, std::string> treeOf(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).generic_string()] = test::readFile(e.path());
  return files;
}

std::vector<uint32_t> wordsOf(const std::string& bytes) {
  std::vector<uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), words.size() * 4);
  return words;
}

// Each target's file of one permutation's fragment shader, checked against the manifest.
void checkFragmentEntry(const fs::path& pkg, const nlohmann::json& p) {
  INFO(p["key"]);
  REQUIRE(p.contains("fragment"));
  const nlohmann::json& f = p["fragment"];
  REQUIRE(f["files"].size() == 5);
  const std::map<std::string, std::string> starts = {{"glsl450", "#version 450"},
                                                     {"essl310", "#version 310 es"},
                                                     {"hlsl", "SPIRV_Cross_Output main("},
                                                     {"msl", "fragment main0_out main0("}};
  for (const auto& [target, file] : f["files"].items()) {
    const std::string path = file.get<std::string>();
    CHECK(path == fragmentPath(target, f["spirv_hash_xxh64"].get<std::string>()));
    REQUIRE(fs::exists(pkg / path));
    if (starts.count(target)) CHECK(test::readFile(pkg / path).find(starts.at(target)) != std::string::npos);
  }
  const std::string spv = test::readFile(pkg / f["files"]["spirv"].get<std::string>());
  CHECK(contentHash(spv.data(), spv.size()) == f["spirv_hash_xxh64"]);
  CHECK(spirvInstructionCount(wordsOf(spv)) == f["spirv_instructions"].get<size_t>());
  // The manifest's reflection is the file's.
  CHECK(reflectSpirv(wordsOf(spv)).dump() == f["reflection"].dump());
  CHECK(f["reflection"]["stage"] == "fragment");
  bool frame = false;
  for (const auto& u : f["reflection"]["uniform_buffers"])
    if (u["binding"] == 1) frame = u["name"] == "MbFrameBlock" && u["size"] == 1872;
  CHECK(frame);
  // Samplers: the environment's and the material's textures, at their documented bindings.
  std::set<int> samplers;
  for (const auto& s : f["reflection"]["sampled_images"]) samplers.insert(s["binding"].get<int>());
  if (p["environment"] == "ibl_lut") {
    CHECK(samplers.count(2));
    CHECK(samplers.count(3));
  }
  // The LTC table at 4 with a rectangle or disk light or a light shaded by the "ltc" method, the
  // material's textures from 5.
  bool area = false;
  for (const auto& l : p["lights"]) area = area || l == "rect" || l == "disk";
  for (const auto& m : p["light_methods"]) area = area || m == "ltc";
  CHECK(samplers.count(4) == (area ? 1u : 0u));
  for (const auto& t : f["textures"]) {
    CHECK(t["binding"].get<int>() >= 5);
    samplers.erase(t["binding"].get<int>());
  }
  samplers.erase(2);
  samplers.erase(3);
  samplers.erase(4);
  CHECK(samplers.empty());
}

}  // namespace

TEST_CASE("compile writes each permutation's fragment shader in every target, with manifest entry and header",
          "[fragment][package]") {
  const fs::path dir = test::freshTempDir("fragment", "package");
  const std::string inputs =
      test::materialPath("worn_car_paint.json") + " " +
      (test::sourceDir() / "examples/gltf/textured_props.gltf").string() +
      " --lights dir,point,spot,sphere,tube,rect,disk --environment ibl_lut --namespace frag_pkg" + kAllTargets;
  const nlohmann::json manifest = compileTo("-j1 " + inputs, dir / "a");
  // Byte-identical at another -j and with one permutation per stream window.
  compileTo("-j2 --stream-window 1 " + inputs, dir / "b");
  const auto files = treeOf(dir / "a");
  CHECK(files == treeOf(dir / "b"));

  CHECK(manifest["fragment"]["interface_version"] == 2);
  CHECK(manifest["fragment"]["frame"]["binding"] == 1);
  REQUIRE(manifest["permutations"].size() == 5);  // worn_car_paint and textured_props' four
  size_t textured = 0;
  for (const auto& p : manifest["permutations"]) {
    checkFragmentEntry(dir / "a", p);
    textured += !p["fragment"]["textures"].empty();
  }
  CHECK(textured >= 2);  // Wood.001 and Lamp Shade carry texture records

  // The header: MbFrameBlock and the bindings, and per permutation its fragment shader.
  std::string tu = "#include \"matbricks_materials.hpp\"\n";
  tu += "static_assert(sizeof(frag_pkg::MbFrameBlock) == 1872);\n";
  tu +=
      "static_assert(frag_pkg::kFragmentFrameBinding == 1 && frag_pkg::kFragmentLtcTableBinding == 4 && "
      "frag_pkg::kFragmentFirstTextureBinding == 5);\n";
  for (const auto& p : manifest["permutations"]) {
    const std::string find = "frag_pkg::findPermutation(\"" + p["key"].get<std::string>() + "\")";
    tu += "static_assert(" + find + "->fragmentSpirv == \"" + p["fragment"]["files"]["spirv"].get<std::string>() +
          "\");\n";
    tu += "static_assert(" + find + "->fragmentTextureCount == " + std::to_string(p["fragment"]["textures"].size()) +
          ");\n";
  }
  tu += "int main() { return 0; }\n";
  std::ofstream(dir / "a" / "use.cpp") << tu;
  const int rc = std::system(("cd " + (dir / "a").string() + " && " + test::cxxCompiler() +
                              " -std=c++17 -Wall -Wextra -Werror -fsyntax-only "
                              "use.cpp > compile.log 2>&1")
                                 .c_str());
  INFO(test::readFile(dir / "a" / "compile.log"));
  CHECK(rc == 0);
  fs::remove_all(dir);
}

TEST_CASE("an fp16 package's fragment shaders: half SPIR-V, ESSL from the mediump form", "[fragment][package]") {
  const fs::path dir = test::freshTempDir("fragment", "fp16");
  const nlohmann::json manifest =
      compileTo(test::materialPath("worn_car_paint.json") +
                    " --precision fp16 --lights dir,sphere --environment ibl_analytic" + kAllTargets,
                dir / "pkg");
  REQUIRE(manifest["permutations"].size() == 1);
  const nlohmann::json& p = manifest["permutations"][0];
  checkFragmentEntry(dir / "pkg", p);
  const std::string essl = test::readFile(dir / "pkg" / p["fragment"]["files"]["essl310"].get<std::string>());
  CHECK(essl.find("mediump") != std::string::npos);
  CHECK(essl.find("float16") == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("the fragment shader is cached with its kernel: a warm build compiles nothing and gives the same bytes",
          "[fragment][cache]") {
  test::ScratchDir dir("fragment_cache");
  const ShaderLibrary& lib = test::shippedLibrary();
  const auto& mats = test::loadedMaterials(lib, {"worn_car_paint", "velvet_green"});
  const auto perms = test::permutationsOf(mats, {"dir", "point"}, EnvironmentMode::IblLut);
  BuildOptions o;
  o.targets = {Target::Spirv, Target::Glsl450, Target::Essl310, Target::Hlsl, Target::Msl};
  o.cacheDir = test::rootOf(dir);
  BuildStats cold, warm;
  const auto first = buildPermutations(lib, perms, o, &cold);
  const auto second = buildPermutations(lib, perms, o, &warm);
  CHECK(cold.compiled == perms.size());
  CHECK(warm.compiled == 0);
  CHECK(warm.cacheHits == perms.size());
  for (size_t i = 0; i < perms.size(); ++i) {
    INFO(perms[i].key());
    CHECK(!first[i].artifacts.fragment.spirv.empty());
    CHECK(first[i].artifacts.fragment.targets.size() == 4);
    CHECK(second[i].fromCache);
    CHECK(first[i].fragmentHash == second[i].fragmentHash);
    CHECK(first[i].artifacts.fragment.spirv == second[i].artifacts.fragment.spirv);
    CHECK(first[i].artifacts.fragment.targets == second[i].artifacts.fragment.targets);
    CHECK(first[i].artifacts.fragment.reflection.dump() == second[i].artifacts.fragment.reflection.dump());
  }
  // Without the fragment stage the unit is another one: its key changes, nothing is shared.
  o.stages.fragment = false;
  BuildStats kernelOnly;
  const auto third = buildPermutations(lib, perms, o, &kernelOnly);
  CHECK(kernelOnly.cacheHits == 0);
  for (const auto& b : third) {
    CHECK(b.fragmentHash.empty());
    CHECK(b.artifacts.fragment.spirv.empty());
  }
  // Without the kernel (compile --stages fragment) likewise; the fragment shaders are those
  // of the build with both, and a second such build takes every unit from the cache.
  o.stages = {false, true};
  BuildStats fragmentOnly, again;
  const auto fourth = buildPermutations(lib, perms, o, &fragmentOnly);
  CHECK(fragmentOnly.cacheHits == 0);
  REQUIRE(fourth.size() == first.size());
  for (size_t i = 0; i < fourth.size(); ++i) {
    CHECK(fourth[i].spirvHash.empty());
    CHECK(fourth[i].artifacts.spirv.empty());
    CHECK(fourth[i].artifacts.fragment.spirv == first[i].artifacts.fragment.spirv);
    CHECK(fourth[i].artifacts.fragment.targets == first[i].artifacts.fragment.targets);
  }
  buildPermutations(lib, perms, o, &again);
  CHECK(again.cacheHits == again.shardUnits);
  CHECK(again.compiled == 0);
}

// The names a WebGL 2.0 program binds: each `uniform NAME` block and sampler the reflection lists
// is declared in the ESSL 3.00 under that name, and the vertex shader's outputs are the fragment
// shader's inputs by name (ES 3.00 has no locations on them).
TEST_CASE("compile --targets webgl2: ESSL 3.00 fragment shaders, the vertex shader once, and the names a program binds",
          "[fragment][package]") {
  const fs::path dir = test::freshTempDir("fragment", "webgl2");
  const std::string inputs = test::materialPath("satin_sheen.json") + " " + test::materialPath("velvet_green.json") +
                             " --lights dir,point,spot --environment ibl_lut --targets webgl2";
  const nlohmann::json manifest = compileTo(inputs, dir / "pkg");
  CHECK(manifest["targets"] == nlohmann::json{"spirv", "webgl2"});
  const nlohmann::json& vertex = manifest["fragment"]["webgl2"];
  CHECK(vertex["file"] == "fragment/webgl2/engine_vertex.webgl2.vert");
  CHECK(vertex["block"]["name"] == "MbVertexPush");
  CHECK(vertex["block"]["size"] == 128);
  CHECK(vertex["attributes"].size() == 4);
  const std::string vert = test::readFile(dir / "pkg" / vertex["file"].get<std::string>());
  CHECK(vert.rfind("#version 300 es\n", 0) == 0);
  CHECK(vert.find("uniform MbVertexPush") != std::string::npos);
  for (const auto& a : vertex["attributes"])
    CHECK(vert.find("layout(location = " + std::to_string(a["location"].get<int>()) + ") in " +
                    a["type"].get<std::string>() + " " + a["name"].get<std::string>() + ";") != std::string::npos);
  REQUIRE(manifest["permutations"].size() == 2);
  for (const auto& p : manifest["permutations"]) {
    INFO(p["key"]);
    const nlohmann::json& f = p["fragment"];
    REQUIRE(f["files"].contains("webgl2"));
    CHECK_FALSE(p["files"].contains("webgl2"));  // no kernel: WebGL 2.0 has no compute
    const std::string frag = test::readFile(dir / "pkg" / f["files"]["webgl2"].get<std::string>());
    CHECK(frag.rfind("#version 300 es\n", 0) == 0);
    CHECK(frag.find("binding") == std::string::npos);
    for (const auto& u : f["reflection"]["uniform_buffers"])
      CHECK(frag.find("uniform " + u["name"].get<std::string>()) != std::string::npos);
    for (const auto& s : f["reflection"]["sampled_images"])
      CHECK(frag.find(s["type"].get<std::string>() + " " + s["name"].get<std::string>() + ";") != std::string::npos);
    for (const auto& in : f["reflection"]["stage_inputs"])
      CHECK(vert.find("out " + in["type"].get<std::string>() + " " + in["name"].get<std::string>() + ";") !=
            std::string::npos);
  }
  // Without the fragment stage there is nothing to build for webgl2: refused before any output.
  auto r = test::runCli("compile -q --no-cache " + test::materialPath("satin_sheen.json") +
                        " --targets webgl2 --stages kernel -o " + (dir / "kernel").string());
  CHECK(r.exitCode == 2);
  CHECK(r.output.find("webgl2") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "kernel"));
  fs::remove_all(dir);
}
