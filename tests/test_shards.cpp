// compile --shard i/N and matbricks merge (compile/shard.hpp, docs/targets.md "Shards"): N
// shards merged give the single-process package byte for byte; every bad set of shards is
// refused with a clear error and writes nothing.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "compile/shard.hpp"
#include "support/cli_support.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

const std::string kScene = (test::sourceDir() / "examples/scenes/showroom.json").string();
const std::string kTargets = " --targets spirv,glsl450,essl310,hlsl,msl";

// Every file under `a` equals the same file under `b`, and neither has one the other lacks.
void requireSameTree(const fs::path& a, const fs::path& b) {
  std::set<std::string> inA, inB;
  for (const auto& e : fs::recursive_directory_iterator(a))
    if (e.is_regular_file()) inA.insert(fs::relative(e.path(), a).string());
  for (const auto& e : fs::recursive_directory_iterator(b))
    if (e.is_regular_file()) inB.insert(fs::relative(e.path(), b).string());
  REQUIRE(inA == inB);
  for (const auto& rel : inA) {
    INFO(rel);
    CHECK(test::readFile(a / rel) == test::readFile(b / rel));
  }
}

// Compiles shards 1..n of the showroom into <root>/s<i>, each with its own empty cache.
void compileShards(const fs::path& root, unsigned n, const std::string& extra = kTargets) {
  for (unsigned i = 1; i <= n; ++i) {
    const std::string spec = std::to_string(i) + "/" + std::to_string(n);
    auto r = test::runCli("compile -q --scene " + kScene + extra + " --shard " + spec + " --cache-dir " +
                          (root / ("c" + std::to_string(i))).string() + " -o " +
                          (root / ("s" + std::to_string(i))).string());
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
  }
}

}  // namespace

TEST_CASE("shard specs: i/N with 1 <= i <= N", "[shards]") {
  ShardSpec s;
  std::string why;
  REQUIRE(parseShardSpec("2/3", s, why));
  CHECK(s.index == 2);
  CHECK(s.count == 3);
  CHECK(s.owns(1));
  CHECK(s.owns(4));
  CHECK(!s.owns(0));
  CHECK(!s.owns(2));
  for (const char* bad : {"0/3", "4/3", "1/0", "3", "a/b", "1/3x", "-1/3", "1/5000", ""}) {
    INFO(bad);
    CHECK(!parseShardSpec(bad, s, why));
    CHECK(!why.empty());
  }
  CHECK(ShardSpec{}.owns(7));
}

TEST_CASE("three shards merged equal the single-process package, byte for byte", "[shards][cli]") {
  const fs::path root = test::freshTempDir("shards", "merge");
  auto whole = test::runCli("compile -q --scene " + kScene + kTargets + " --no-cache -o " + (root / "whole").string());
  REQUIRE(whole.exitCode == 0);
  compileShards(root, 3);

  // The shards split the units: disjoint, together all of them, sizes differing by one at most.
  std::set<std::string> keys;
  size_t entries = 0, units = 0;
  std::vector<size_t> sizes;
  for (int i = 1; i <= 3; ++i) {
    const fs::path s = root / ("s" + std::to_string(i));
    CHECK(fs::exists(s / ".matbricks-package"));
    auto j = nlohmann::json::parse(test::readFile(s / "shard.json"));
    CHECK(j["shard"] == i);
    CHECK(j["of"] == 3);
    units = j["units"].get<size_t>();
    sizes.push_back(j["entries"].size());
    for (const auto& e : j["entries"]) {
      keys.insert(e["key"].get<std::string>());
      CHECK(fs::exists(s / "entries" / (e["key"].get<std::string>() + ".mbc")));
      ++entries;
    }
  }
  CHECK(entries == units);
  CHECK(keys.size() == units);
  CHECK(*std::max_element(sizes.begin(), sizes.end()) - *std::min_element(sizes.begin(), sizes.end()) <= 1);

  // Order of the arguments does not matter.
  auto merged = test::runCli("merge " + (root / "s3").string() + " " + (root / "s1").string() + " " +
                             (root / "s2").string() + " -o " + (root / "merged").string());
  INFO(merged.output);
  REQUIRE(merged.exitCode == 0);
  CHECK(merged.output.find("merged from 3 shard(s), 0 compiled") != std::string::npos);
  requireSameTree(root / "whole", root / "merged");

  // One shard of one is the whole build too.
  compileShards(root / "single", 1);
  REQUIRE(test::runCli("merge -q " + (root / "single/s1").string() + " -o " + (root / "merged1").string()).exitCode ==
          0);
  requireSameTree(root / "whole", root / "merged1");
  fs::remove_all(root);
}

TEST_CASE("merge refuses an incomplete, mixed, stale or damaged set of shards and writes nothing", "[shards][cli]") {
  const fs::path root = test::freshTempDir("shards", "bad");
  compileShards(root, 3, "");
  const std::string s1 = (root / "s1").string(), s2 = (root / "s2").string(), s3 = (root / "s3").string();
  const std::string out = (root / "out").string();
  auto expectRefused = [&](const std::string& args, const std::string& code) {
    auto r = test::runCli("merge " + args + " -o " + out);
    INFO(args << "\n" << r.output);
    CHECK(r.exitCode == 3);
    CHECK(r.output.find(code) != std::string::npos);
    CHECK(!fs::exists(out));
  };
  expectRefused(s1 + " " + s3, "E-SHARD-INCOMPLETE");                        // shard 2 missing
  expectRefused(s1 + " " + s2 + " " + s3 + " " + s2, "E-SHARD-INCOMPLETE");  // given twice
  expectRefused((test::sourceDir() / "materials").string(), "E-SHARD-NOT-SHARD");
  expectRefused((root / "nowhere").string(), "E-SHARD-NOT-SHARD");

  // A shard of another split.
  compileShards(root / "two", 2, "");
  expectRefused(s1 + " " + (root / "two/s2").string() + " " + s3, "E-SHARD-MISMATCH");

  // An entry deleted, then one truncated: the shard that should hold it is named.
  const fs::path entries = root / "s2/entries";
  const fs::path victim = fs::directory_iterator(entries)->path();
  const std::string bytes = test::readFile(victim);
  fs::remove(victim);
  expectRefused(s1 + " " + s2 + " " + s3, "E-SHARD-CORRUPT");
  std::ofstream(victim, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  expectRefused(s1 + " " + s2 + " " + s3, "E-SHARD-CORRUPT");
  std::ofstream(victim, std::ios::binary | std::ios::trunc) << bytes;
  REQUIRE(test::runCli("merge -q " + s1 + " " + s2 + " " + s3 + " -o " + out).exitCode == 0);
  fs::remove_all(out);

  // Entries swapped, or one replaced by a link (to another entry, to /dev/zero) or a FIFO:
  // each is E-SHARD-CORRUPT naming the entry (never an internal error), and nothing is written.
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(entries)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 2);
  const std::string first = test::readFile(files[0]), second = test::readFile(files[1]);
  auto expectCorruptEntry = [&](const fs::path& entry) {
    auto r = test::runCli("merge " + s1 + " " + s2 + " " + s3 + " -o " + out);
    INFO(r.output);
    CHECK(r.exitCode == 3);
    CHECK(r.output.find(entry.string() + ": error[E-SHARD-CORRUPT]") != std::string::npos);
    CHECK(!fs::exists(out));
  };
  std::ofstream(files[0], std::ios::binary | std::ios::trunc) << second;
  std::ofstream(files[1], std::ios::binary | std::ios::trunc) << first;
  expectCorruptEntry(files[0]);
  std::ofstream(files[1], std::ios::binary | std::ios::trunc) << second;  // files[1] right again
  fs::remove(files[0]);
  fs::create_symlink(files[1], files[0]);
  expectCorruptEntry(files[0]);
  fs::remove(files[0]);
  fs::create_symlink("/dev/zero", files[0]);
  expectCorruptEntry(files[0]);
  fs::remove(files[0]);
  REQUIRE(::mkfifo(files[0].c_str(), 0600) == 0);
  expectCorruptEntry(files[0]);
  fs::remove(files[0]);
  std::ofstream(files[0], std::ios::binary) << first;
  REQUIRE(test::runCli("merge -q " + s1 + " " + s2 + " " + s3 + " -o " + out).exitCode == 0);
  fs::remove_all(out);

  // Inputs that changed since the shards were compiled: another plan.
  const fs::path work = root / "work";
  fs::create_directories(work / "materials");
  fs::copy(test::sourceDir() / "materials/ue4_metal.json", work / "materials/m.json");
  auto local = [&](const std::string& args) { return test::runCli(args, "", work.string()); };
  REQUIRE(local("compile -q materials/m.json --no-cache --shard 1/1 -o s").exitCode == 0);
  REQUIRE(local("merge -q s -o p1").exitCode == 0);  // paths in shard.json are the user's, as given
  // A constant the shader bakes in: another emitted GLSL, so another cache key.
  std::string text = test::readFile(work / "materials/m.json");
  const std::string before = "\"default\": 1.0, \"constant\": true";
  REQUIRE(text.find(before) != std::string::npos);
  text.replace(text.find(before), before.size(), "\"default\": 0.5, \"constant\": true");
  std::ofstream(work / "materials/m.json", std::ios::trunc) << text;
  auto stale = local("merge s -o p2");
  INFO(stale.output);
  CHECK(stale.exitCode == 3);
  CHECK(stale.output.find("E-SHARD-MISMATCH") != std::string::npos);
  CHECK(!fs::exists(work / "p2"));

  // The output may not be a shard, and a shard directory never replaces a user's directory.
  auto overlap = test::runCli("merge " + s1 + " " + s2 + " " + s3 + " -o " + s2);
  CHECK(overlap.exitCode == 3);
  CHECK(fs::exists(root / "s2/shard.json"));
  fs::create_directories(root / "mine");
  std::ofstream(root / "mine/notes.txt") << "mine";
  auto refused =
      test::runCli("compile -q --scene " + kScene + " --shard 1/2 --no-cache -o " + (root / "mine").string());
  CHECK(refused.exitCode == 3);
  CHECK(test::readFile(root / "mine/notes.txt") == "mine");

  // A shard.json that is not JSON, or has a field of the wrong type: located.
  fs::copy(root / "s1", root / "broken", fs::copy_options::recursive);
  std::ofstream(root / "broken/shard.json", std::ios::trunc)
      << "{ \"format\": \"matbricks-shard-1\",\n  \"shard\": 1,, }";
  auto broken = test::runCli("merge " + (root / "broken").string() + " -o " + out);
  CHECK(broken.exitCode == 3);
  CHECK(broken.output.find("broken/shard.json:2:14: error[E-JSON-SYNTAX]") != std::string::npos);
  std::ofstream(root / "broken/shard.json", std::ios::trunc)
      << "{ \"format\": \"matbricks-shard-1\", \"shard\": \"x\" }";
  broken = test::runCli("merge " + (root / "broken").string() + " -o " + out);
  CHECK(broken.exitCode == 3);
  CHECK(broken.output.find("broken/shard.json:1:43: error[E-SHARD-NOT-SHARD]") != std::string::npos);
  CHECK(!fs::exists(out));

  // Usage errors exit 2.
  CHECK(test::runCli("compile --scene " + kScene + " --stream-window -1 -o " + out).exitCode == 2);
  CHECK(test::runCli("compile --scene " + kScene + " --shard 4/3 -o " + out).exitCode == 2);
  CHECK(test::runCli("compile --scene " + kScene + " --shard 1/2 --depfile d -o " + out).exitCode == 2);
  CHECK(test::runCli("merge -o " + out).exitCode == 2);
  fs::remove_all(root);
}

TEST_CASE("two swapped entries of a one-shard split are refused, not merged into a wrong package", "[shards][cli]") {
  // Two permutations that differ only in the environment: each entry is a valid entry, of
  // the other permutation's unit.
  const fs::path root = test::freshTempDir("shards", "swap");
  fs::copy(test::sourceDir() / "materials/ue4_metal.json", root / "m.json");
  std::ofstream(root / "scene.json") << R"({"name": "two", "lights": [{"type": "dir", "name": "sun"}],
    "environment": ["none", "sh"], "precision": "fp32", "quality": "high", "targets": ["spirv"],
    "materials": [{"file": "m.json"}]})";
  auto local = [&](const std::string& args) { return test::runCli(args, "", root.string()); };
  auto shard = local("compile -q --scene scene.json --no-cache --shard 1/1 -o s");
  INFO(shard.output);
  REQUIRE(shard.exitCode == 0);
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(root / "s/entries")) files.push_back(e.path());
  REQUIRE(files.size() == 2);
  const std::string a = test::readFile(files[0]), b = test::readFile(files[1]);
  std::ofstream(files[0], std::ios::binary | std::ios::trunc) << b;
  std::ofstream(files[1], std::ios::binary | std::ios::trunc) << a;
  auto merged = local("merge s -o p");
  INFO(merged.output);
  CHECK(merged.exitCode == 3);
  CHECK(merged.output.find("error[E-SHARD-CORRUPT]") != std::string::npos);
  CHECK(merged.output.find("holds the entry of another unit") != std::string::npos);
  CHECK(!fs::exists(root / "p"));
  // Put back, it merges into the package a plain compile writes.
  std::ofstream(files[0], std::ios::binary | std::ios::trunc) << a;
  std::ofstream(files[1], std::ios::binary | std::ios::trunc) << b;
  REQUIRE(local("merge -q s -o p").exitCode == 0);
  REQUIRE(local("compile -q --scene scene.json --no-cache -o whole").exitCode == 0);
  requireSameTree(root / "whole", root / "p");
  fs::remove_all(root);
}
