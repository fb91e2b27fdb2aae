// The matbricks command line, run as a user would run it.
#include <catch2/catch.hpp>

#include <set>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "support/cli_support.hpp"
#include "support/pipeline_support.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

fs::path tempDir(const std::string& name) { return test::freshTempDir("cli", name); }

std::string material(const std::string& file) { return test::materialPath(file); }

// Two in-domain CSV rows for a brick, built from `bricks --json` alone.
std::string csvFor(const nlohmann::json& brick) {
  std::string header, row1, row2;
  for (const auto& col : brick["inputs"]) {
    std::string c = col.get<std::string>();
    double v1 = 0.5, v2 = 0.25;
    if (c.size() == 3 && c[1] == '.') {  // vector component: n, v, l, or a vec3 parameter
      char vec = c[0], axis = c[2];
      if (vec == 'n') v1 = v2 = axis == 'z' ? 1.0 : 0.0;
      if (vec == 'v') {
        v1 = axis == 'x' ? 0.6 : (axis == 'z' ? 0.8 : 0.0);
        v2 = axis == 'z' ? 1.0 : 0.0;
      }
      if (vec == 'l') {
        v1 = axis == 'x' ? -0.6 : (axis == 'z' ? 0.8 : 0.0);
        v2 = axis == 'y' ? 0.6 : (axis == 'z' ? 0.8 : 0.0);
      }
    }
    std::string key = c.substr(0, c.find('.'));
    if (brick["domain"].contains(key)) {
      // 70% and 90% of the range: the midpoint of a signed vector domain [-1, 1] would be
      // the zero vector, which has no direction.
      double lo = brick["domain"][key][0], hi = brick["domain"][key][1];
      v1 = lo + 0.7 * (hi - lo);
      v2 = lo + 0.9 * (hi - lo);
    }
    header += (header.empty() ? "" : ",") + c;
    row1 += (row1.empty() ? "" : ",") + std::to_string(v1);
    row2 += (row2.empty() ? "" : ",") + std::to_string(v2);
  }
  return header + "\n" + row1 + "\n" + row2 + "\n";
}

}  // namespace

TEST_CASE("without a Vulkan device, validate prints one clear line and exits 4", "[cli][harness]") {
  auto r = test::runCli("validate " + material("filament_plastic.json"),
                        "VK_ICD_FILENAMES=/nonexistent/none.json VK_DRIVER_FILES=/nonexistent/none.json");
  CHECK(r.exitCode == 4);
  CHECK_THAT(r.output, Catch::StartsWith("error: no Vulkan device"));
  CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
}

TEST_CASE("a malformed material exits 3 with file:line:column", "[cli][diagnostics]") {
  fs::path dir = tempDir("bad");
  { std::ofstream(dir / "bad.json") << "{\n  \"name\": \"x\",\n  \"model\": \"standard\"\n  \"bricks\": {}\n}\n"; }
  auto r = test::runCli("compile " + (dir / "bad.json").string() + " -o " + (dir / "pkg").string());
  CHECK(r.exitCode == 3);
  CHECK_THAT(r.output, Catch::Contains((dir / "bad.json").string() + ":4:3: error[E-JSON-SYNTAX]"));
  CHECK_FALSE(fs::exists(dir / "pkg"));
  fs::remove_all(dir);
}

TEST_CASE("compile writes a complete, deterministic package", "[cli][package]") {
  fs::path dir = tempDir("pkg");
  std::string inputs;
  for (const auto& f : test::exampleMaterialFiles()) inputs += " " + f;
  auto a = test::runCli("compile" + inputs + " -o " + (dir / "a").string());
  auto b = test::runCli("compile -q" + inputs + " -o " + (dir / "b").string());
  REQUIRE(a.exitCode == 0);
  REQUIRE(b.exitCode == 0);
  auto manifest = nlohmann::json::parse(test::readFile(dir / "a/manifest.json"));
  REQUIRE(manifest["permutations"].size() == test::exampleMaterialFiles().size());
  std::set<std::string> hashes, fragments;
  for (const auto& p : manifest["permutations"]) {
    CHECK(fs::exists(dir / "a" / p["files"]["spirv"].get<std::string>()));
    CHECK(fs::exists(dir / "a" / p["fragment"]["files"]["spirv"].get<std::string>()));
    fragments.insert(p["fragment"]["spirv_hash_xxh64"].get<std::string>());
    CHECK(fs::exists(dir / "a" / p["include"].get<std::string>()));
    CHECK(p["spirv_instructions"].get<int>() > 0);
    hashes.insert(p["spirv_hash_xxh64"].get<std::string>());
  }
  // docs/package.md: marker, manifest, header, one include per permutation, one SPIR-V per
  // hash, one fragment SPIR-V per fragment hash.
  size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir / "a")) {
    if (!e.is_regular_file()) continue;
    ++files;
    fs::path rel = fs::relative(e.path(), dir / "a");
    INFO(rel);
    CHECK(test::readFile(e.path()) == test::readFile(dir / "b" / rel));
  }
  CHECK(fs::exists(dir / "a/matbricks_materials.hpp"));
  CHECK(files == 3 + manifest["permutations"].size() + hashes.size() + fragments.size());
  fs::remove_all(dir);
}

TEST_CASE("a failing compile leaves an existing package untouched", "[cli][package]") {
  fs::path dir = tempDir("atomic");
  REQUIRE(test::runCli("compile -q " + material("ue4_metal.json") + " -o " + (dir / "pkg").string()).exitCode == 0);
  std::string before = test::readFile(dir / "pkg/manifest.json");
  {
    std::ofstream(dir / "unknown_brick.json")
        << R"({"name": "m", "model": "standard", "bricks": {"roughness": "roughness_clamped", "diffuse": "diffuse_lambert", "specular_d": "d_ggxx", "specular_v": "v_smith_ggx_correlated", "fresnel": "f_schlick"}})";
  }
  auto r = test::runCli("compile " + material("ue4_metal.json") + " " + (dir / "unknown_brick.json").string() + " -o " +
                        (dir / "pkg").string());
  CHECK(r.exitCode == 3);
  CHECK_THAT(r.output, Catch::Contains("E-UNKNOWN-BRICK"));
  CHECK_THAT(r.output, Catch::Contains("d_ggx"));
  CHECK(test::readFile(dir / "pkg/manifest.json") == before);
  size_t entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    (void)e;
    ++entries;
  }
  CHECK(entries == 2);  // pkg and the bad material: no staging directory left behind
  fs::remove_all(dir);
}

TEST_CASE("eval works for every brick that bricks --json lists", "[cli][eval][vulkan]") {
  auto list = test::runCli("bricks --json");
  REQUIRE(list.exitCode == 0);
  auto bricks = nlohmann::json::parse(list.output);
  REQUIRE(!bricks.empty());
  fs::path dir = tempDir("eval");
  for (const auto& b : bricks) {
    std::string id = b["id"];
    fs::path csv = dir / (id + ".csv");
    { std::ofstream(csv) << csvFor(b); }
    auto r = test::runCli("--vk-validation eval --json --brick " + id + " --input " + csv.string());
    INFO(id << ": " << r.output);
    CHECK(r.exitCode == 0);
    auto out = nlohmann::json::parse(r.output.substr(0, r.output.rfind('}') + 1), nullptr, false);
    REQUIRE_FALSE(out.is_discarded());
    CHECK(out["rows"].size() == 2);
    CHECK(out["passed"] == true);
  }
  fs::remove_all(dir);
}

TEST_CASE("eval --material evaluates a whole material; a bad CSV header is located", "[cli][eval][vulkan]") {
  fs::path dir = tempDir("evalmat");
  {
    std::ofstream(dir / "in.csv")
        << "n.x,n.y,n.z,v.x,v.y,v.z,l.x,l.y,l.z,roughness\n0,0,1,0.6,0,0.8,-0.6,0,0.8,0.3\n0,0,1,0,0,1,0,0,1,0.05\n";
  }
  auto r = test::runCli("eval --material " + material("ue4_metal.json") + " --input " + (dir / "in.csv").string());
  INFO(r.output);
  CHECK(r.exitCode == 0);
  CHECK_THAT(r.output, Catch::Contains("within tolerance"));
  {
    std::ofstream(dir / "bad.csv") << "n.x,n.y,n.z,v.x,v.y,v.z,l.x,l.y,l.z,roughnes\n0,0,1,0.6,0,0.8,-0.6,0,0.8,0.3\n";
  }
  auto bad = test::runCli("eval --material " + material("ue4_metal.json") + " --input " + (dir / "bad.csv").string());
  CHECK(bad.exitCode == 3);
  CHECK_THAT(bad.output, Catch::Contains("bad.csv:1:37: error[E-CSV-COLUMN]: unknown column 'roughnes'"));
  CHECK_THAT(bad.output, Catch::Contains("did you mean 'roughness'"));
  fs::remove_all(dir);
}

TEST_CASE("validate --json gives one complete record per permutation", "[cli][validate][vulkan]") {
  auto r = test::runCli("--vk-validation validate --json --samples 512 " + material("filament_plastic.json") + " " +
                        material("ue4_metal.json"));
  REQUIRE(r.exitCode == 0);
  auto recs = nlohmann::json::parse(r.output);
  // Two materials, each with every light type of the standard model, once per environment mode.
  REQUIRE(recs.size() == 8);
  std::set<std::string> keys;
  for (const auto& rec : recs) keys.insert(rec["key"].get<std::string>());
  CHECK(keys.count("filament_plastic.standard.dir+point+spot+sphere+tube+rect+disk.ibl_lut.fp32"));
  CHECK(keys.count("ue4_metal.standard.dir+point+spot+sphere+tube+rect+disk.none.fp32"));
  for (const auto& rec : recs) {
    for (const char* k : {"key", "samples", "max_abs_error", "max_rel_error", "max_ulp", "nan_count", "inf_count",
                          "negative_count", "passed", "gpu_ms"})
      CHECK(rec.contains(k));
    CHECK(rec["passed"] == true);
    CHECK(rec["nan_count"] == 0);
    CHECK(rec["samples"] == 512);
  }
}

TEST_CASE("a list option takes one word per use, never the arguments after it", "[cli]") {
  const fs::path dir = test::freshTempDir("cli", "list_options");
  const std::string material = test::materialPath("ue4_metal.json");
  auto r = test::runCli("compile -q --no-cache --targets msl " + material + " --lights dir,point --targets hlsl -o " +
                        (dir / "p").string());
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  const auto manifest = nlohmann::json::parse(test::readFile(dir / "p" / "manifest.json"));
  CHECK(manifest["targets"] == nlohmann::json::array({"spirv", "hlsl", "msl"}));
  CHECK(manifest["permutations"][0]["lights"] == nlohmann::json::array({"dir", "point"}));
  // Space-separated values are not a list: the second word would be a material path; as it is
  // no file but a light type, that is the usage error, with the comma-separated form.
  auto words = test::runCli("compile -q --no-cache --lights dir point " + material + " -o " + (dir / "q").string());
  CHECK(words.exitCode == 2);
  CHECK_THAT(words.output, Catch::Contains("--lights dir,point"));
  CHECK_FALSE(fs::exists(dir / "q"));
}

TEST_CASE("every subcommand has --help and usage errors exit 2", "[cli]") {
  for (const char* sub :
       {"compile", "validate", "bricks", "eval", "stress", "energy", "lut", "ltc", "bench", "preview"}) {
    auto r = test::runCli(std::string(sub) + " --help");
    INFO(sub);
    CHECK(r.exitCode == 0);
    CHECK_THAT(r.output, Catch::Contains("Usage"));
  }
  CHECK(test::runCli("").exitCode == 2);
  CHECK(test::runCli("frobnicate").exitCode == 2);
  CHECK(test::runCli("eval --input x.csv").exitCode == 2);
  CHECK(test::runCli("stress --precision fp64").exitCode == 2);
  CHECK(test::runCli("lut --size 0").exitCode == 2);
  CHECK(test::runCli("ltc --size 1 -o t.json").exitCode == 2);
  CHECK(test::runCli("ltc --size 8").exitCode == 2);  // no -o
  CHECK(test::runCli("energy --grid huge").exitCode == 2);
  CHECK(test::runCli("bench --repeats 0").exitCode == 2);
  CHECK(test::runCli("bricks --no-gpu").exitCode == 2);             // needs --markdown -o FILE
  CHECK(test::runCli("bricks --markdown --no-gpu").exitCode == 2);  // the figures come from FILE
}

TEST_CASE("every example eval input evaluates within tolerance", "[cli][eval][examples][vulkan]") {
  // examples/eval/brick.<id>.<label>.csv and material.<name>.<label>.csv (examples/README.md).
  size_t count = 0;
  for (const auto& e : fs::directory_iterator(test::sourceDir() / "examples" / "eval")) {
    std::string name = e.path().filename().string();
    if (e.path().extension() != ".csv") continue;
    auto dot1 = name.find('.'), dot2 = name.find('.', dot1 + 1);
    REQUIRE(dot2 != std::string::npos);
    std::string kind = name.substr(0, dot1), id = name.substr(dot1 + 1, dot2 - dot1 - 1);
    std::string target = kind == "brick" ? "--brick " + id : "--material " + material(id + ".json");
    auto r = test::runCli("eval " + target + " --input " + e.path().string());
    INFO(name << "\n" << r.output);
    CHECK(r.exitCode == 0);
    CHECK_THAT(r.output, Catch::Contains("within tolerance"));
    ++count;
  }
  CHECK(count >= 2);
}

TEST_CASE("eval --material takes an optional illuminance column; a partial one is located", "[cli][eval][vulkan]") {
  fs::path dir = tempDir("illum");
  const std::string header = "n.x,n.y,n.z,v.x,v.y,v.z,l.x,l.y,l.z,";
  {
    std::ofstream(dir / "lit.csv")
        << header << "illuminance.x,illuminance.y,illuminance.z,roughness\n0,0,1,0.6,0,0.8,-0.6,0,0.8,1000,500,2,0.5\n";
  }
  { std::ofstream(dir / "partial.csv") << header << "illuminance.x,roughness\n0,0,1,0,0,1,0,0,1,2,0.5\n"; }
  auto lit = test::runCli("eval --material " + material("ue4_metal.json") + " --input " + (dir / "lit.csv").string());
  INFO(lit.output);
  CHECK(lit.exitCode == 0);
  CHECK_THAT(lit.output, Catch::Contains("within tolerance"));
  auto partial =
      test::runCli("eval --material " + material("ue4_metal.json") + " --input " + (dir / "partial.csv").string());
  INFO(partial.output);
  CHECK(partial.exitCode == 3);
  CHECK_THAT(partial.output, Catch::Contains((dir / "partial.csv").string() + ":1:1: error[E-CSV-COLUMN]"));
  CHECK_THAT(partial.output, Catch::Contains("illuminance.y"));
  fs::remove_all(dir);
}

TEST_CASE("compile's scene, target and cache options: usage errors exit 2; an unusable cache is no error",
          "[cli][scene]") {
  fs::path dir = tempDir("compile_options");
  const std::string scene = (test::sourceDir() / "examples/scenes/mobile.json").string();
  const std::string out = " -o " + (dir / "pkg").string();
  struct Usage {
    std::string args, says;
  };
  for (const Usage& u : {Usage{"compile --scene " + scene + " " + material("ue4_metal.json") + out, "not both"},
                         Usage{"compile --scene " + scene + " --lights dir" + out, "conflicts with --scene"},
                         Usage{"compile " + material("ue4_metal.json") + " --targets dxil" + out, "dxil"},
                         Usage{"compile " + material("ue4_metal.json"), "-o DIR"},
                         // A space-separated list: the rest would read as material files.
                         Usage{"compile " + material("ue4_metal.json") + " --targets spirv hlsl" + out,
                               "'hlsl' is a target, not a material file: --targets takes one comma-separated list "
                               "(e.g. --targets spirv,hlsl)"},
                         Usage{"compile " + material("ue4_metal.json") + " --lights dir point" + out,
                               "'point' is a light type, not a material file: --lights takes one comma-separated "
                               "list (e.g. --lights dir,point)"}}) {
    auto r = test::runCli(u.args);
    INFO(u.args << "\n" << r.output);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find(u.says) != std::string::npos);
    CHECK(!fs::exists(dir / "pkg"));
  }
  // A cache path that cannot be a directory (a regular file): the build goes on uncached.
  std::ofstream(dir / "not_a_dir") << "x";
  auto r = test::runCli("compile " + material("ue4_metal.json") + " --cache-dir " + (dir / "not_a_dir").string() + out);
  INFO(r.output);
  CHECK(r.exitCode == 0);
  CHECK(fs::exists(dir / "pkg" / "manifest.json"));
  fs::remove_all(dir);
}
