// Issue 18, "Done means": every file of the glTF conformance corpus
// (tests/data/gltf_conformance/, one concern per file, README there) compiles with `compile`
// and with `compile --scene`, through the CLI a user runs; the manifest keeps what the engine
// needs. The numeric checks against the glTF spec's formulas are test_gltf_conventions.cpp.
#include <catch2/catch.hpp>
#include <algorithm>
#include <fstream>
#include <set>
#include <nlohmann/json.hpp>

#include "support/cli_support.hpp"

using namespace mb;
using nlohmann::json;

namespace {

std::filesystem::path corpus() { return test::sourceDir() / "tests/data/gltf_conformance"; }

std::vector<std::string> corpusFiles() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(corpus()))
    if (e.path().extension() == ".gltf" || e.path().extension() == ".glb")
      files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

json manifestOf(const std::filesystem::path& package) {
  std::ifstream in(package / "manifest.json");
  return json::parse(in);
}

struct Compiled {
  test::CliResult cli;
  json manifest;
};

// `compile [--scene] FILE -o DIR` (SPIR-V only, no cache: each run really compiles).
Compiled compile(const std::string& file, bool scene, const std::string& extra = "") {
  std::filesystem::path out = test::freshTempDir("gltf_conformance", (scene ? "scene_" : "") + file) / "pkg";
  std::string args = "compile " + std::string(scene ? "--scene " : "") + "'" + (corpus() / file).string() + "' -o '" +
                     out.string() + "' --no-cache " + extra;
  Compiled c{test::runCli(args), json()};
  if (c.cli.exitCode == 0) c.manifest = manifestOf(out);
  return c;
}

std::set<std::string> environmentsOf(const json& manifest) {
  std::set<std::string> envs;
  for (const auto& p : manifest.at("permutations")) envs.insert(p.at("environment").get<std::string>());
  return envs;
}

}  // namespace

TEST_CASE("every file of the glTF conformance corpus compiles and scene-compiles", "[gltf][gltf-conformance]") {
  std::vector<std::string> files = corpusFiles();
  REQUIRE(files.size() == 11);
  for (const auto& file : files) {
    for (bool scene : {false, true}) {
      Compiled c = compile(file, scene);
      INFO(file << (scene ? " (--scene)" : "") << ":\n" << c.cli.output);
      CHECK(c.cli.exitCode == 0);
      CHECK(c.cli.output.find("E-INTERNAL") == std::string::npos);
      if (c.cli.exitCode == 0) CHECK_FALSE(c.manifest.at("permutations").empty());
    }
  }
}

// Item 1: a texture input that does not reach a permutation's output (occlusion without an
// environment to occlude) leaves no parameter block; the package says so instead of failing.
TEST_CASE("a parameter block the optimizer removed is no internal error", "[gltf][gltf-conformance]") {
  for (const char* env : {"none", "sh"}) {
    Compiled c = compile("occlusion_only.gltf", false, std::string("--environment ") + env);
    INFO(env << ":\n" << c.cli.output);
    REQUIRE(c.cli.exitCode == 0);
    for (const auto& p : c.manifest.at("permutations")) {
      INFO(p.at("key"));
      CHECK(p.at("parameters").size() >= 1);
      bool block = false;
      for (const auto& u : p.at("reflection").value("uniform_buffers", json::array()))
        block |= u.value("binding", -1) == 2;
      if (std::string(env) == "none") CHECK_FALSE(block);
    }
  }
  // With the image-based light the scene plans, the occlusion reaches the output.
  Compiled lit = compile("occlusion_only.gltf", true);
  REQUIRE(lit.cli.exitCode == 0);
  for (const auto& p : lit.manifest.at("permutations")) {
    bool block = false;
    for (const auto& u : p.at("reflection").value("uniform_buffers", json::array()))
      block |= u.value("binding", -1) == 2;
    CHECK(block);
  }
}

// Items 4 and 5: the environment a glTF scene gets, and the warnings that say why.
TEST_CASE("glTF scenes plan the environment a viewer shows", "[gltf][gltf-conformance]") {
  Compiled ibl = compile("image_based_light.gltf", true);
  INFO(ibl.cli.output);
  REQUIRE(ibl.cli.exitCode == 0);
  CHECK(environmentsOf(ibl.manifest) == std::set<std::string>{"ibl_lut"});
  CHECK(ibl.cli.output.find("W-GLTF-UNSUPPORTED-EXTENSION") == std::string::npos);
  CHECK(ibl.cli.output.find("W-SCENE-GLTF-NO-LIGHTS") == std::string::npos);

  Compiled dark = compile("textured_no_lights.glb", true);
  INFO(dark.cli.output);
  REQUIRE(dark.cli.exitCode == 0);
  CHECK(environmentsOf(dark.manifest) == std::set<std::string>{"ibl_lut"});
  CHECK(dark.cli.output.find("W-SCENE-GLTF-NO-LIGHTS") != std::string::npos);

  Compiled lit = compile("anisotropy.gltf", true);
  REQUIRE(lit.cli.exitCode == 0);
  CHECK(environmentsOf(lit.manifest) == std::set<std::string>{"none"});
  CHECK(lit.cli.output.find("W-SCENE-GLTF-NO-LIGHTS") == std::string::npos);
}

// Item 3: mesh and image extensions, even required, do not concern materials.
TEST_CASE("required Draco and BasisU do not reject a glTF file", "[gltf][gltf-conformance]") {
  Compiled c = compile("required_engine_extensions.gltf", false);
  INFO(c.cli.output);
  CHECK(c.cli.exitCode == 0);
  CHECK(c.cli.output.find("KHR_draco_mesh_compression") == std::string::npos);
  CHECK(c.cli.output.find("KHR_texture_basisu") == std::string::npos);
}

// Item 10: alpha, sidedness, texture transforms and the anisotropy rotation reach the manifest;
// a .glb whose BIN chunk is shorter than its buffer is a warning.
TEST_CASE("the manifest keeps what the engine needs of a glTF material", "[gltf][gltf-conformance]") {
  Compiled c = compile("engine_data.gltf", false);
  INFO(c.cli.output);
  REQUIRE(c.cli.exitCode == 0);
  const json& engine = c.manifest.at("permutations").at(0).at("engine");
  CHECK(engine.at("alphaMode") == "MASK");
  CHECK(engine.at("alphaCutoff").get<double>() == 0.3);
  CHECK(engine.at("doubleSided") == true);
  const json& texture = engine.at("textures").at(0);
  CHECK(texture.at("parameter") == "baseColorTexture");
  const json& transform = texture.at("KHR_texture_transform");
  CHECK(transform.at("offset") == json::array({0.5, 0.25}));
  CHECK(transform.at("rotation").get<double>() == 1.5707963);
  CHECK(transform.at("scale") == json::array({2.0, 3.0}));
  CHECK(transform.at("texCoord") == 1);

  Compiled aniso = compile("anisotropy.gltf", false);
  REQUIRE(aniso.cli.exitCode == 0);
  CHECK(aniso.manifest.at("permutations").at(0).at("engine").at("anisotropyRotation").get<double>() == 0.5);

  Compiled shortBin = compile("short_bin.glb", false);
  INFO(shortBin.cli.output);
  CHECK(shortBin.cli.exitCode == 0);
  CHECK(shortBin.cli.output.find("warning[W-GLB-BIN-SHORT]") != std::string::npos);
  CHECK(shortBin.cli.output.find("declares 64 bytes, but its BIN chunk holds 16") != std::string::npos);
}

// Item 5 inside scene JSON: its own lights count, and its "environment" wins.
TEST_CASE("scene JSON naming a glTF without lights: the same default, overridable", "[gltf][gltf-conformance]") {
  std::filesystem::path dir = test::freshTempDir("gltf_conformance", "scene_json");
  auto scene = [&](const std::string& name, const std::string& extra) {
    std::filesystem::path p = dir / name;
    std::ofstream(p) << R"({"gltf": ")" << (corpus() / "occlusion_only.gltf").string() << "\"" << extra << "}";
    return p.string();
  };
  struct Case {
    std::string extra;
    std::set<std::string> environments;
    bool warned;
  };
  for (const Case& c : {Case{"", {"ibl_lut"}, true}, Case{R"(, "environment": ["sh"])", {"sh"}, false},
                        Case{R"(, "lights": [{"type": "dir"}])", {"none"}, false}}) {
    std::filesystem::path out = dir / "pkg";
    test::CliResult r =
        test::runCli("compile --scene '" + scene("s.json", c.extra) + "' -o '" + out.string() + "' --no-cache");
    INFO(c.extra << ":\n" << r.output);
    REQUIRE(r.exitCode == 0);
    CHECK(environmentsOf(manifestOf(out)) == c.environments);
    CHECK((r.output.find("W-SCENE-GLTF-NO-LIGHTS") != std::string::npos) == c.warned);
  }
}

// The numeric checks run the probe in-process (test_gltf_conventions.cpp); this is the same
// through `matbricks eval`, as a user would: the emission at strength 1500.
TEST_CASE("eval evaluates a glTF material from the corpus", "[gltf][gltf-conformance][vulkan]") {
  std::filesystem::path csv = test::freshTempDir("gltf_conformance", "eval") / "below_horizon.csv";
  std::ofstream(csv) << "n.x,n.y,n.z,v.x,v.y,v.z,l.x,l.y,l.z\n0,0,1,0,0,1,0,0.6,-0.8\n";
  test::CliResult r = test::runCli("eval --material '" + (corpus() / "emissive_strength.gltf").string() +
                                   "' --input '" + csv.string() + "' --json");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  json out = json::parse(r.output.substr(r.output.find('{')));
  const json& gpu = out.at("rows").at(0).at("gpu");
  CHECK(gpu.at("out.x").get<double>() == 1500.0);
  CHECK(gpu.at("out.y").get<double>() == 750.0);
  CHECK(gpu.at("out.z").get<double>() == 375.0);
}
