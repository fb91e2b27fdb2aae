// compile -O0|-O1|-O2 (docs/performance-compile.md "Levels"): each level's package is
// byte-identical at every -j, the manifest names the level, the levels give different SPIR-V
// for fp32 units and the same for fp16 kernels (always unoptimized), a scene's level is used
// unless -O overrides it, and the cache keeps the levels apart.
#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "support/cli_support.hpp"

namespace fs = std::filesystem;
using namespace mb;

namespace {

const char* const kLevels[] = {"-O0", "-O1", "-O2"};

using Package = test::CompiledPackage;

// Sum of spirv_instructions over the permutations of one precision.
size_t instructions(const nlohmann::json& manifest, const std::string& precision) {
  size_t n = 0;
  for (const auto& p : manifest["permutations"])
    if (p["precision"] == precision) n += p["spirv_instructions"].get<size_t>();
  return n;
}

std::set<std::string> hashes(const nlohmann::json& manifest, const std::string& precision) {
  std::set<std::string> h;
  for (const auto& p : manifest["permutations"])
    if (p["precision"] == precision) h.insert(p["spirv_hash_xxh64"].get<std::string>());
  return h;
}

}  // namespace

TEST_CASE("every optimization level is byte-identical at every -j and named in the manifest", "[cli][levels]") {
  const fs::path dir = test::freshTempDir("levels", "jobs");
  const std::string inputs = test::materialPath("ue4_metal.json") + " " + test::materialPath("filament_plastic.json") +
                             " --targets spirv,glsl450,hlsl --no-cache";
  std::map<std::string, Package> byLevel;
  for (const char* level : kLevels) {
    INFO(level);
    const Package one = test::compilePackage(std::string(level) + " -j1 " + inputs, dir / (std::string(level) + "_j1"));
    const Package two = test::compilePackage(std::string(level) + " -j2 " + inputs, dir / (std::string(level) + "_j2"));
    CHECK(one.files == two.files);
    CHECK(one.manifest["optimization"] == std::string(level).substr(1));
    byLevel[level] = one;
  }
  // The default is O2: the same package as -O2.
  CHECK(test::compilePackage("-j2 " + inputs, dir / "default").files == byLevel["-O2"].files);

  // spirv-opt did something at O1 and more at O2: every level's SPIR-V differs, and O0 (no
  // spirv-opt) has the most instructions.
  const size_t o0 = instructions(byLevel["-O0"].manifest, "fp32"), o1 = instructions(byLevel["-O1"].manifest, "fp32"),
               o2 = instructions(byLevel["-O2"].manifest, "fp32");
  CHECK(o0 > o1);
  CHECK(o0 > o2);
  CHECK(hashes(byLevel["-O0"].manifest, "fp32") != hashes(byLevel["-O1"].manifest, "fp32"));
  CHECK(hashes(byLevel["-O1"].manifest, "fp32") != hashes(byLevel["-O2"].manifest, "fp32"));
}

TEST_CASE("fp16 kernels are unoptimized at every level", "[cli][levels]") {
  const fs::path dir = test::freshTempDir("levels", "fp16");
  const std::string inputs = test::materialPath("ue4_metal.json") + " --precision fp16 --no-cache";
  const Package o0 = test::compilePackage("-O0 " + inputs, dir / "o0");
  const Package o2 = test::compilePackage("-O2 " + inputs, dir / "o2");
  CHECK(hashes(o0.manifest, "fp16") == hashes(o2.manifest, "fp16"));
  CHECK(o0.manifest["optimization"] == "O0");
  CHECK(o2.manifest["optimization"] == "O2");
}

TEST_CASE("a scene's optimization level is used, and -O overrides it", "[cli][levels][scene]") {
  const fs::path dir = test::freshTempDir("levels", "scene");
  const fs::path scene = dir / "scene.json";
  std::ofstream(scene) << R"({"lights": [{"type": "dir"}], "optimization": "O0", "materials": [{"file": ")"
                       << test::materialPath("ue4_metal.json") << "\"}]}";
  const Package fromScene = test::compilePackage("--no-cache --scene " + scene.string(), dir / "scene");
  CHECK(fromScene.manifest["optimization"] == "O0");
  const Package o0 = test::compilePackage("--no-cache -O0 " + test::materialPath("ue4_metal.json"), dir / "o0");
  CHECK(hashes(fromScene.manifest, "fp32") == hashes(o0.manifest, "fp32"));
  const Package overridden = test::compilePackage("--no-cache -O2 --scene " + scene.string(), dir / "overridden");
  CHECK(overridden.manifest["optimization"] == "O2");
  CHECK(hashes(overridden.manifest, "fp32") != hashes(o0.manifest, "fp32"));
}

TEST_CASE("the compile cache keeps the levels apart", "[cli][levels][cache]") {
  const fs::path dir = test::freshTempDir("levels", "cache");
  const std::string compile =
      "compile " + test::materialPath("filament_plastic.json") + " --cache-dir " + (dir / "cache").string();
  auto run = [&](const std::string& level, const std::string& out) {
    auto r = test::runCli(compile + " " + level + " -o " + (dir / out).string());
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    return r.output;
  };
  CHECK_THAT(run("-O2", "a"), Catch::Contains("1 compiled, 0 cached"));
  CHECK_THAT(run("-O0", "b"), Catch::Contains("1 compiled, 0 cached"));
  CHECK_THAT(run("-O1", "c"), Catch::Contains("1 compiled, 0 cached"));
  CHECK_THAT(run("-O0", "d"), Catch::Contains("0 compiled, 1 cached"));
  CHECK(test::readFile(dir / "b/manifest.json") == test::readFile(dir / "d/manifest.json"));
}

TEST_CASE("compile -O and bench -O refuse a level that does not exist", "[cli][levels]") {
  const fs::path dir = test::freshTempDir("levels", "bad");
  auto r = test::runCli("compile -O3 " + test::materialPath("ue4_metal.json") + " -o " + (dir / "p").string());
  CHECK(r.exitCode == 2);
  CHECK_FALSE(fs::exists(dir / "p"));
  auto bench = test::runCli("bench -O3 " + test::materialPath("ue4_metal.json") + " -o " + (dir / "b").string());
  INFO(bench.output);
  CHECK(bench.exitCode == 2);
  CHECK_THAT(bench.output, Catch::Contains("--optimization"));
  CHECK_FALSE(fs::exists(dir / "b"));
}
