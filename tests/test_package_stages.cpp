// compile --stages (docs/package.md "Stages"): a package of fragment shaders only, or of kernels
// only, holds exactly that stage's files, byte for byte those of the package with both, is
// byte-identical at every -j, records its stages in the manifest and shard.json (a merge gives
// the single compile's package), and `validate` still compiles the kernel it needs, through
// the same cache, from a cache a fragment-only compile filled.
#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <set>

#include "support/cli_support.hpp"

namespace fs = std::filesystem;
using namespace mb;

namespace {

const std::string kInputs = test::materialPath("ue4_metal.json") + " " + test::materialPath("filament_plastic.json") +
                            " --targets spirv,glsl450 --no-cache";

// The package's files under `prefix` (e.g. "fragment/"), or outside every prefix given.
std::map<std::string, std::string> filesUnder(const test::CompiledPackage& p, const std::string& prefix) {
  std::map<std::string, std::string> out;
  for (const auto& [path, bytes] : p.files)
    if (path.rfind(prefix, 0) == 0) out[path] = bytes;
  return out;
}

size_t filesIn(const fs::path& dir) {
  size_t n = 0;
  if (fs::exists(dir))
    for (const auto& e : fs::recursive_directory_iterator(dir)) n += e.is_regular_file();
  return n;
}

}  // namespace

TEST_CASE("compile --stages writes exactly the chosen stages, the same bytes as with both", "[cli][stages]") {
  const fs::path dir = test::freshTempDir("stages", "files");
  const auto both = test::compilePackage("-j2 " + kInputs, dir / "both");
  const auto fragment = test::compilePackage("-j2 --stages fragment " + kInputs, dir / "fragment");
  const auto kernel = test::compilePackage("-j2 --stages kernel " + kInputs, dir / "kernel");

  CHECK(both.manifest["stages"] == nlohmann::json::array({"kernel", "fragment"}));
  CHECK(fragment.manifest["stages"] == nlohmann::json::array({"fragment"}));
  CHECK(kernel.manifest["stages"] == nlohmann::json::array({"kernel"}));
  // Naming both, in either order, is the default.
  CHECK(test::compilePackage("-j2 --stages fragment,kernel " + kInputs, dir / "named").files == both.files);

  // Fragment only: the fragment shaders and includes of the full package, no kernel module.
  CHECK_FALSE(filesUnder(fragment, "fragment/").empty());
  CHECK(filesUnder(fragment, "fragment/") == filesUnder(both, "fragment/"));
  CHECK(filesUnder(fragment, "include/") == filesUnder(both, "include/"));
  CHECK(filesUnder(fragment, "spirv/").empty());
  CHECK(filesUnder(fragment, "glsl450/").empty());
  CHECK_FALSE(fragment.manifest.contains("kernel"));
  CHECK(fragment.manifest.contains("fragment"));
  for (const auto& p : fragment.manifest["permutations"]) {
    INFO(p["key"]);
    CHECK_FALSE(p.contains("spirv_hash_xxh64"));
    CHECK_FALSE(p.contains("files"));
    CHECK_FALSE(p.contains("reflection"));
    REQUIRE(p.contains("fragment"));
    CHECK(p["fragment"]["files"].contains("glsl450"));
  }
  // Its header points at fragment shaders only; the parameter struct comes from the fragment
  // shader's block.
  const std::string& header = fragment.files.at("matbricks_materials.hpp");
  CHECK(header.find("\"spirv/") == std::string::npos);
  CHECK(header.find("\"fragment/spirv/") != std::string::npos);
  CHECK(header.find("std140 block MbMaterialParams (set 0, binding 0)") != std::string::npos);

  // Kernels only: the kernel modules of the full package, no fragment shader.
  CHECK(filesUnder(kernel, "fragment/").empty());
  CHECK(filesUnder(kernel, "spirv/") == filesUnder(both, "spirv/"));
  CHECK(filesUnder(kernel, "glsl450/") == filesUnder(both, "glsl450/"));
  CHECK(filesUnder(kernel, "include/") == filesUnder(both, "include/"));
  CHECK_FALSE(kernel.manifest.contains("fragment"));
  CHECK(kernel.manifest.contains("kernel"));
  for (const auto& p : kernel.manifest["permutations"]) CHECK_FALSE(p.contains("fragment"));
  CHECK(kernel.files.at("matbricks_materials.hpp").find("\"fragment/") == std::string::npos);
}

TEST_CASE("a fragment-only package is byte-identical at every -j", "[cli][stages]") {
  const fs::path dir = test::freshTempDir("stages", "jobs");
  const auto one = test::compilePackage("-j1 --stages fragment " + kInputs, dir / "j1");
  const auto two = test::compilePackage("-j2 --stages fragment " + kInputs, dir / "j2");
  CHECK(one.files == two.files);
}

TEST_CASE("compile refuses a bad --stages list and writes nothing", "[cli][stages]") {
  const fs::path dir = test::freshTempDir("stages", "usage");
  for (const char* bad : {"vertex", "kernel,kernel", "kernel,", "\"\""}) {
    INFO(bad);
    auto r = test::runCli("compile --stages " + std::string(bad) + " " + test::materialPath("ue4_metal.json") + " -o " +
                          (dir / "out").string());
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("--stages") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "out"));
  }
}

TEST_CASE("shards record their stages and merge into the single compile's package", "[cli][stages][shards]") {
  const fs::path dir = test::freshTempDir("stages", "shards");
  const std::string inputs = "--stages fragment " + kInputs;
  const auto single = test::compilePackage(inputs, dir / "single");
  for (const char* i : {"1", "2"})
    REQUIRE(test::runCli("compile -q " + inputs + " --shard " + i + "/2 -o " + (dir / ("s" + std::string(i))).string())
                .exitCode == 0);
  CHECK(test::readFile(dir / "s1" / "shard.json").find("\"stages\": \"fragment\"") != std::string::npos);
  auto merged = test::runCli("merge -q " + (dir / "s1").string() + " " + (dir / "s2").string() + " -o " +
                             (dir / "merged").string());
  INFO(merged.output);
  REQUIRE(merged.exitCode == 0);
  for (const auto& [path, bytes] : single.files) CHECK(test::readFile(dir / "merged" / path) == bytes);

  // A shard.json whose stages, level or targets the command line would have refused is bad input
  // (both shards edited alike, so that they still agree with each other).
  std::map<fs::path, std::string> originals;
  for (const char* s : {"s1", "s2"}) originals[dir / s / "shard.json"] = test::readFile(dir / s / "shard.json");
  for (const auto& [from, to] :
       std::vector<std::pair<std::string, std::string>>{{"\"stages\": \"fragment\"", "\"stages\": \"vertex\""},
                                                        {"\"optimization\": \"\"", "\"optimization\": \"O7\""},
                                                        {"\"glsl450\"", "\"glsl451\""}}) {
    for (const auto& [path, original] : originals) {
      std::string edited = original;
      REQUIRE(edited.find(from) != std::string::npos);
      edited.replace(edited.find(from), from.size(), to);
      std::ofstream(path, std::ios::binary | std::ios::trunc) << edited;
    }
    auto r = test::runCli("merge " + (dir / "s1").string() + " " + (dir / "s2").string() + " -o " +
                          (dir / "refused").string());
    INFO(to << "\n" << r.output);
    CHECK(r.exitCode == 3);
    CHECK(r.output.find("E-SHARD-NOT-SHARD") != std::string::npos);
    CHECK(r.output.find("'" + to.substr(1, to.find('"', 1) - 1) + "'") != std::string::npos);  // names the field
    CHECK_FALSE(fs::exists(dir / "refused"));
  }
}

TEST_CASE("validate compiles the kernel a fragment-only compile did not, through the same cache",
          "[cli][stages][vulkan]") {
  const fs::path dir = test::freshTempDir("stages", "validate");
  const fs::path cache = dir / "cache";
  const std::string env = "MATBRICKS_CACHE_DIR=" + cache.string();
  const std::string material = test::materialPath("filament_plastic.json");
  auto compiled = test::runCli("compile -q --stages fragment " + material + " -o " + (dir / "pkg").string(), env);
  INFO(compiled.output);
  REQUIRE(compiled.exitCode == 0);
  const size_t afterCompile = filesIn(cache);
  CHECK(afterCompile > 0);
  auto first = test::runCli("validate " + material + " --environment none", env);
  INFO(first.output);
  REQUIRE(first.exitCode == 0);
  const size_t afterValidate = filesIn(cache);
  CHECK(afterValidate > afterCompile);  // the probe kernel, compiled on demand and cached
  auto second = test::runCli("validate " + material + " --environment none", env);
  REQUIRE(second.exitCode == 0);
  CHECK(filesIn(cache) == afterValidate);  // taken from the cache
}
