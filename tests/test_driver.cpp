// The compile driver (driver/compile_run.hpp) without the command line: a CompileRequest run
// directly writes the package `matbricks compile` writes for the same request, byte for byte,
// hands each built permutation to its hook, and refuses what the command line refuses.
#include <catch2/catch.hpp>

#include <set>

#include "driver/compile_run.hpp"
#include "support/cli_support.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

const std::string kMobile = (test::sourceDir() / "examples/scenes/mobile.json").string();

std::map<std::string, std::string> filesUnder(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).generic_string()] = test::readFile(e.path());
  return out;
}

}  // namespace

TEST_CASE("driver: a scene compiled through a CompileRequest is the CLI's package", "[driver][scene][package]") {
  const fs::path root = test::freshTempDir("driver", "scene");
  CompileRequest r;
  r.scene = kMobile;
  r.out = (root / "driver").string();
  r.noCache = true;
  r.jobs = 2;
  r.explain = true;
  std::vector<std::string> built;
  std::string explained;
  CompileHooks hooks;
  hooks.built = [&](const BuiltPermutation& b) { built.push_back(b.shader.key); };
  hooks.explain = [&](const std::string& text) { explained += text; };
  const CompileOutcome outcome = runCompile(r, hooks);

  // The mobile scene: 3 materials x 2 quality levels (docs/scenes.md).
  CHECK(outcome.stats.permutations == 6);
  CHECK(built.size() == 6);
  CHECK(std::set<std::string>(built.begin(), built.end()).size() == 6);
  CHECK(explained.rfind("possible", 0) == 0);
  CHECK(explained.find("required        6") != std::string::npos);
  CHECK(outcome.shard.whole());

  const test::CompiledPackage cli = test::compilePackage("--no-cache -j 2 --scene " + kMobile, root / "cli");
  const auto files = filesUnder(root / "driver");
  CHECK(files.size() == cli.files.size());
  for (const auto& [rel, bytes] : cli.files) {
    INFO(rel);
    REQUIRE(files.count(rel) == 1);
    CHECK(files.at(rel) == bytes);
  }
  fs::remove_all(root);
}

TEST_CASE("driver: a request's shard.json form reads back to the same request", "[driver][shard]") {
  CompileRequest r;
  r.materials = {"a.json", "b.mat"};
  r.lights = {LightType::Dir, LightType::Sphere};
  r.environment = EnvironmentMode::IblAnalytic;
  r.precision = Precision::Fp16;
  r.quality = Quality::Low;
  r.targets = {Target::Spirv, Target::Msl};
  r.optimization = "O1";
  r.stages = "fragment";
  r.headerName = "m.hpp";
  r.cppNamespace = "game";
  r.shaderlib = "/lib";
  const nlohmann::json j = compileRequestJson(r);
  CompileRequest back;
  compileRequestFromJson(j, "shard.json", back);
  CHECK(compileRequestJson(back) == j);
  CHECK(environmentModeName(back.environment) == "ibl_analytic");
  CHECK(lightTypeNames(back.lights) == std::vector<std::string>{"dir", "sphere"});
  CHECK(back.precision == Precision::Fp16);
  CHECK(back.quality == Quality::Low);
  CHECK(back.targets == std::vector<Target>{Target::Spirv, Target::Msl});
  CHECK(j.at("precision") == "fp16");
  CHECK(j.at("targets") == nlohmann::json{"spirv", "msl"});
  CHECK(back.shaderlib == "/lib");

  nlohmann::json bad = j;
  bad["environment"] = "ibl";
  try {
    compileRequestFromJson(bad, "shard.json", back);
    FAIL("an unknown environment mode was read");
  } catch (const DiagnosticError& e) {
    CHECK(e.diagnostics().front().code == "E-PERMUTATION-INVALID");
    CHECK(e.diagnostics().front().where.file == "shard.json");
  }
  bad = j;
  bad["precision"] = "fp64";
  try {
    compileRequestFromJson(bad, "shard.json", back);
    FAIL("an unknown precision was read");
  } catch (const DiagnosticError& e) {
    CHECK(e.diagnostics().front().code == "E-PRECISION");
  }
}

TEST_CASE("driver: what the command line refuses as usage is a CompileUsageError", "[driver][cli]") {
  CompileRequest neither;
  CHECK_THROWS_AS(runCompile(neither), CompileUsageError);
  CompileRequest noOutput;
  noOutput.scene = kMobile;
  CHECK_THROWS_WITH(runCompile(noOutput), "compile needs -o DIR (or --explain, which only counts)");
  // The axes and targets are values (an unknown name cannot be put in a request); the
  // optimization level is kept as written, and refused here as the command line refuses it.
  CompileRequest badLevel;
  badLevel.materials = {test::materialPath("ue4_metal.json")};
  badLevel.explain = true;
  badLevel.optimization = "O5";
  CHECK_THROWS_AS(runCompile(badLevel), CompileUsageError);
}
