// The result cache (core/result_cache.hpp) and the report's use of it (report/result_memo.hpp,
// docs/report.md "Result cache"): what a warm cache saves is counted, never timed.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <string>

#include "core/result_cache.hpp"
#include "support/cli_support.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

void overwrite(const fs::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << bytes;
}

}  // namespace

TEST_CASE("the result cache returns what was stored and rejects damaged or foreign entries", "[result-cache]") {
  const fs::path dir = test::freshTempDir("result-cache", "entries");
  ResultCache cache(dir);
  REQUIRE(cache.enabled());
  const std::vector<std::string> key{"device", "spirv=1234"}, other{"device", "spirv=5678"};
  const double inf = std::numeric_limits<double>::infinity();
  const nlohmann::json value{{"ns", 0.1 + 0.2}, {"max", jsonNumber(inf)}, {"nan", jsonNumber(std::nan(""))}};

  CHECK(!cache.load("cost", key));
  cache.store("cost", key, value);
  auto hit = cache.load("cost", key);
  REQUIRE(hit);
  CHECK(numberFromJson(hit->at("ns")) == 0.1 + 0.2);  // the same double, not a rounded print
  CHECK(numberFromJson(hit->at("max")) == inf);
  CHECK(std::isnan(numberFromJson(hit->at("nan"))));
  CHECK_THROWS(numberFromJson(nlohmann::json("fast")));
  CHECK(!cache.load("albedo", key));  // another kind of result under the same key parts
  CHECK(!cache.load("cost", other));

  const fs::path entry = cache.entryPath("cost", key);
  const std::string bytes = test::readFile(entry);
  SECTION("truncated") { overwrite(entry, bytes.substr(0, bytes.size() / 2)); }
  SECTION("a value edited without its check") {
    std::string edited = bytes;
    edited.replace(edited.find("0.30000000000000004"), 19, "0.20000000000000004");
    overwrite(entry, edited);
  }
  SECTION("another key's entry copied over it") {
    cache.store("cost", other, value);
    overwrite(entry, test::readFile(cache.entryPath("cost", other)));
  }
  SECTION("not a file") {
    fs::remove(entry);
    fs::create_directory(entry);
  }
  const ResultCache::Counts before = cache.counts("cost");
  CHECK(!cache.load("cost", key));
  const ResultCache::Counts after = cache.counts("cost");
  CHECK(after.misses == before.misses + 1);
  CHECK(after.rejected == before.rejected + 1);
  fs::remove_all(entry);
  cache.store("cost", key, value);  // measured again and stored whole
  CHECK(cache.load("cost", key) == value);

  ResultCache off{fs::path()};
  CHECK(!off.enabled());
  off.store("cost", key, value);
  CHECK(!off.load("cost", key));
  fs::remove_all(dir);
}

namespace {

// Two one-permutation materials, one slot chart, the lobes they use; no previews, no LUT
// (neither is cached), the fewest samples and repeats the options allow.
const char* kCacheOptions =
    " --lights dir --environment none --slot fresnel --samples 64 --slot-samples 16 --repeats 1 --target-ms 0.5"
    " --no-lut --no-previews";

struct Use {
  int cached = -1, total = -1;
};

// "N of M <what>" from the report's header.
Use cacheUse(const std::string& html, const std::string& what) {
  std::smatch m;
  if (!std::regex_search(html, m, std::regex("(\\d+) of (\\d+) " + what))) return {};
  return {std::stoi(m[1]), std::stoi(m[2])};
}

// The cost cells of the permutation rows (bench's formatCostWithInterval).
std::vector<std::string> costCells(const std::string& html) {
  static const std::regex cell(R"(<td>([^<]*ns[^<]*)</td>)");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), cell); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1]);
  return out;
}

}  // namespace

TEST_CASE(
    "a second report reads every cost, slot item and albedo from the result cache, and an edit recomputes "
    "only its material",
    "[report][vulkan][result-cache]") {
  const fs::path dir = test::freshTempDir("report", "result-cache");
  const fs::path cacheDir = dir / "cache";
  const std::string env = "MATBRICKS_CACHE_DIR=" + cacheDir.string();
  // Scratch copies: `b` is edited between runs.
  const std::string plastic = test::readFile(test::materialPath("filament_plastic.json"));
  overwrite(dir / "a.json", plastic);
  std::string b = plastic;
  b.replace(b.find("\"filament_plastic\""), 18, "\"scratch_plastic\"");
  overwrite(dir / "b.json", b);
  auto report = [&](const std::string& out) {
    auto r = test::runCli("report " + (dir / "a.json").string() + " " + (dir / "b.json").string() + kCacheOptions +
                              " -q -o " + (dir / out).string(),
                          env);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    return test::readFile(dir / out / "index.html");
  };

  const std::string cold = report("cold");
  const Use costs = cacheUse(cold, "permutation costs"), bricks = cacheUse(cold, "slot chart bricks"),
            lobes = cacheUse(cold, "lobe albedos");
  CHECK(costs.cached == 0);
  CHECK(costs.total == 2);
  CHECK(bricks.cached == 0);
  CHECK(bricks.total >= 2);  // the fresnel slot's bricks
  CHECK(lobes.cached == 0);
  CHECK(lobes.total >= 2);  // GGX with its V, and Lambert

  const std::string warm = report("warm");
  CHECK(cacheUse(warm, "permutation costs").cached == 2);
  CHECK(cacheUse(warm, "slot chart bricks").cached == bricks.total);
  CHECK(cacheUse(warm, "lobe albedos").cached == lobes.total);
  CHECK_THAT(warm, Catch::Contains("measured by an earlier run"));
  // The numbers from the cache are the first run's, exactly: the cost cells, and the charts
  // drawn from the slot items and the albedos.
  CHECK(costCells(warm) == costCells(cold));
  CHECK(costCells(cold).size() >= 2);
  for (const auto& e : fs::recursive_directory_iterator(dir / "cold")) {
    const fs::path rel = fs::relative(e.path(), dir / "cold");
    if (e.path().extension() != ".svg") continue;
    INFO(rel);
    CHECK(test::readFile(dir / "warm" / rel) == test::readFile(e.path()));
  }

  // An edited material recomputes its own entries only.
  const size_t metallic = b.find("\"range\": [0.0, 1.0]}", b.find("\"metallic\""));
  b.replace(metallic, 20, "\"range\": [0.0, 0.5]}");  // metallic's range (its default is 0)
  overwrite(dir / "b.json", b);
  const std::string edited = report("edited");
  CHECK(cacheUse(edited, "permutation costs").cached == 1);
  CHECK(cacheUse(edited, "slot chart bricks").cached == bricks.total);
  CHECK(cacheUse(edited, "lobe albedos").cached == lobes.total);

  // A damaged entry is measured again, and said so.
  size_t damaged = 0;
  for (const auto& e : fs::recursive_directory_iterator(cacheDir / "results" / "lobe-albedo"))
    if (e.is_regular_file() && damaged++ == 0) {
      const std::string bytes = test::readFile(e.path());
      overwrite(e.path(), bytes.substr(0, bytes.size() - 7));
    }
  REQUIRE(damaged == size_t(lobes.total));
  const std::string again = report("damaged");
  CHECK(cacheUse(again, "lobe albedos").cached == lobes.total - 1);
  CHECK_THAT(again, Catch::Contains("1 damaged entries measured again"));
  CHECK(cacheUse(again, "permutation costs").cached == 2);

  // --no-cache measures everything.
  auto r = test::runCli(
      "report " + (dir / "a.json").string() + kCacheOptions + " --no-cache -q -o " + (dir / "off").string(), env);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(test::readFile(dir / "off" / "index.html"), Catch::Contains("result cache off"));
  fs::remove_all(dir);
}
