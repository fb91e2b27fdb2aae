// The on-disk compile cache (compile/shader_cache.hpp): keys, entries, corruption, and
// concurrent builds sharing one directory. Every test uses its own scratch directory.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <fstream>
#include <thread>

#include "compile/shader_cache.hpp"
#include "compile/targets.hpp"
#include "support/build_support.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

CompiledArtifacts sampleArtifacts() {
  CompiledArtifacts a;
  a.spirv = {0x07230203, 0x00010300, 7, 42, 0, 1, 2, 3};
  a.targets["glsl450"] = "#version 450\nvoid main() {}\n";
  a.targets["msl"] = std::string("kernel\0with a NUL", 17);
  a.reflection = {{"entry_point", "main"}, {"workgroup_size", {64, 1, 1}}};
  return a;
}

void requireSame(const CompiledArtifacts& a, const CompiledArtifacts& b) {
  CHECK(a.spirv == b.spirv);
  CHECK(a.targets == b.targets);
  CHECK(a.reflection == b.reflection);
}

std::vector<Permutation> cachePermutations() {
  const auto& mats = test::loadedMaterials(test::shippedLibrary(), {"filament_plastic", "satin_sheen", "ue4_metal"});
  return test::permutationsOf(mats, {"dir", "point"}, EnvironmentMode::Sh);
}

// The identity an entry file carries.
CacheIdentity identityIn(const fs::path& entry) {
  CacheIdentity found;
  CompiledArtifacts a;
  decodeCacheEntry(test::readFile(entry), CacheIdentity{}, a, &found);
  return found;
}

// Every entry under `dir` is its own key's and loads as a hit, and no temporary file is left behind.
size_t requireAllEntriesValid(const ShaderCache& cache) {
  size_t entries = 0;
  for (const auto& e : fs::recursive_directory_iterator(cache.dir())) {
    if (!e.is_regular_file()) continue;
    INFO(e.path());
    REQUIRE(e.path().extension() == ".mbc");
    const CacheIdentity id = identityIn(e.path());
    CHECK(id.key == e.path().stem().string());
    CompiledArtifacts a;
    CHECK(cache.load(id, a) == ShaderCache::Lookup::Hit);
    ++entries;
  }
  return entries;
}

CacheIdentity sampleIdentity(const std::string& name) {
  return ShaderCache::identity(ShaderCache::key({name}), {"void main() {} // " + name});
}

}  // namespace

TEST_CASE("cache keys are 128-bit hex, length-prefixed and order-sensitive", "[cache]") {
  const std::string k = ShaderCache::key({"a", "bc"});
  CHECK(k.size() == 32);
  CHECK(k.find_first_not_of("0123456789abcdef") == std::string::npos);
  CHECK(k == ShaderCache::key({"a", "bc"}));
  CHECK(k != ShaderCache::key({"ab", "c"}));
  CHECK(k != ShaderCache::key({"bc", "a"}));
  CHECK(k != ShaderCache::key({"a", "bc", ""}));
}

TEST_CASE("a stored entry loads back whole; a missing one misses; a disabled cache does nothing", "[cache]") {
  test::ScratchDir dir("cache_roundtrip");
  ShaderCache cache(test::rootOf(dir));
  const CacheIdentity id = sampleIdentity("roundtrip");
  const std::string& key = id.key;
  CompiledArtifacts out;
  CHECK(cache.load(id, out) == ShaderCache::Lookup::Miss);
  REQUIRE(cache.store(id, sampleArtifacts()));
  CHECK(cache.entryPath(key) == test::rootOf(dir) / key.substr(0, 2) / (key + ".mbc"));
  REQUIRE(cache.load(id, out) == ShaderCache::Lookup::Hit);
  requireSame(out, sampleArtifacts());
  CHECK(identityIn(cache.entryPath(key)) == id);

  ShaderCache off{fs::path()};
  CHECK(!off.enabled());
  CHECK(!off.store(id, sampleArtifacts()));
  CHECK(off.load(id, out) == ShaderCache::Lookup::Miss);
}

TEST_CASE("a corrupt entry is detected, deleted and reported", "[cache]") {
  test::ScratchDir dir("cache_corrupt");
  ShaderCache cache(test::rootOf(dir));
  const CacheIdentity id = sampleIdentity("corrupt");
  const std::string& key = id.key;
  REQUIRE(cache.store(id, sampleArtifacts()));
  const std::string good = test::readFile(cache.entryPath(key));
  REQUIRE(good.size() > 40);

  auto corruptWith = [&](const std::string& bytes) {
    { std::ofstream(cache.entryPath(key), std::ios::binary | std::ios::trunc) << bytes; }
    CompiledArtifacts out;
    CHECK(cache.load(id, out) == ShaderCache::Lookup::Corrupt);
    CHECK(!fs::exists(cache.entryPath(key)));
  };
  SECTION("truncated") { corruptWith(good.substr(0, good.size() - 3)); }
  SECTION("truncated inside the header") { corruptWith(good.substr(0, 20)); }
  SECTION("empty") { corruptWith(""); }
  SECTION("one payload byte flipped") {
    std::string bad = good;
    bad[bad.size() / 2] ^= 0x10;
    corruptWith(bad);
  }
  SECTION("bad magic") {
    std::string bad = good;
    bad[0] = 'X';
    corruptWith(bad);
  }
  SECTION("another format version") {
    std::string bad = good;
    bad[9] ^= 1;  // the format tag follows the 8-byte magic
    corruptWith(bad);
  }
  SECTION("trailing bytes") { corruptWith(good + "x"); }
}

TEST_CASE("an intact entry of another unit, or no regular file, at a key's path is evicted, never believed",
          "[cache]") {
  test::ScratchDir dir("cache_other_unit");
  ShaderCache cache(test::rootOf(dir));
  const CacheIdentity a = sampleIdentity("a"), b = sampleIdentity("b");
  CompiledArtifacts other = sampleArtifacts();
  other.spirv.back() = 99;
  REQUIRE(cache.store(a, sampleArtifacts()));
  REQUIRE(cache.store(b, other));
  CompiledArtifacts out;
  std::string why;

  SECTION("two entry files swapped") {
    const std::string bytesA = test::readFile(cache.entryPath(a.key)), bytesB = test::readFile(cache.entryPath(b.key));
    { std::ofstream(cache.entryPath(a.key), std::ios::binary | std::ios::trunc) << bytesB; }
    { std::ofstream(cache.entryPath(b.key), std::ios::binary | std::ios::trunc) << bytesA; }
    CHECK(cache.load(a, out, &why) == ShaderCache::Lookup::OtherUnit);
    CHECK(why.find(b.key) != std::string::npos);
    CHECK(why.find(cache.entryPath(a.key).string()) != std::string::npos);
    CHECK(!fs::exists(cache.entryPath(a.key)));
    CHECK(cache.load(b, out) == ShaderCache::Lookup::OtherUnit);
    CHECK(out.spirv.empty());  // untouched
  }
  SECTION("the right key, another unit's source") {
    const CacheIdentity sameKeyOtherSource{a.key, b.source};
    CHECK(cache.load(sameKeyOtherSource, out) == ShaderCache::Lookup::OtherUnit);
  }
  SECTION("a symlink to another entry") {
    fs::remove(cache.entryPath(a.key));
    fs::create_symlink(cache.entryPath(b.key), cache.entryPath(a.key));
    CHECK(cache.load(a, out) == ShaderCache::Lookup::OtherUnit);
    CHECK(!fs::exists(fs::symlink_status(cache.entryPath(a.key))));
    CHECK(cache.load(b, out) == ShaderCache::Lookup::Hit);  // what it pointed to is untouched
  }
  SECTION("a symlink to /dev/zero, a FIFO, a directory: unreadable at once, evicted") {
    fs::remove(cache.entryPath(a.key));
    fs::create_symlink("/dev/zero", cache.entryPath(a.key));
    CHECK(cache.load(a, out, &why) == ShaderCache::Lookup::Unreadable);
    CHECK(!why.empty());
    CHECK(!fs::exists(fs::symlink_status(cache.entryPath(a.key))));
    REQUIRE(::mkfifo(cache.entryPath(a.key).c_str(), 0600) == 0);
    CHECK(cache.load(a, out) == ShaderCache::Lookup::Unreadable);
    CHECK(!fs::exists(fs::symlink_status(cache.entryPath(a.key))));
    fs::create_directories(cache.entryPath(a.key));
    CHECK(cache.load(a, out) == ShaderCache::Lookup::Unreadable);
    REQUIRE(cache.store(b, other));  // the cache goes on
  }
}

TEST_CASE("builds through the cache: a warm build hits, a corrupt entry is rebuilt to identical output",
          "[cache][build]") {
  test::ScratchDir dir("cache_build");
  const ShaderLibrary& lib = test::shippedLibrary();
  auto perms = cachePermutations();
  BuildOptions o;
  o.targets = {Target::Spirv, Target::Glsl450, Target::Hlsl};
  o.cacheDir = test::rootOf(dir);
  o.jobs = 2;
  BuildStats cold, warm, repaired;
  auto first = buildPermutations(lib, perms, o, &cold);
  CHECK(cold.compiled == perms.size());
  CHECK(cold.cacheHits == 0);
  ShaderCache cache(test::rootOf(dir));
  CHECK(requireAllEntriesValid(cache) == perms.size());

  auto second = buildPermutations(lib, perms, o, &warm);
  CHECK(warm.compiled == 0);
  CHECK(warm.cacheHits == perms.size());
  for (const auto& b : second) CHECK(b.fromCache);
  test::requireIdentical(first, second);

  // Flip one byte of one entry: detected, rebuilt, stored again, output unchanged.
  fs::path entry;
  for (const auto& e : fs::recursive_directory_iterator(test::rootOf(dir)))
    if (e.is_regular_file()) entry = e.path();
  std::string bytes = test::readFile(entry);
  bytes[bytes.size() - 5] ^= 0x01;
  { std::ofstream(entry, std::ios::binary | std::ios::trunc) << bytes; }
  auto third = buildPermutations(lib, perms, o, &repaired);
  CHECK(repaired.cacheCorrupt == 1);
  CHECK(repaired.compiled == 1);
  CHECK(repaired.cacheHits == perms.size() - 1);
  test::requireIdentical(first, third);
  CHECK(requireAllEntriesValid(cache) == perms.size());
  CHECK(repaired.cacheWarnings.empty());  // a damaged entry is counted, not warned about

  // Two entry files swapped: both are another unit's, evicted and rebuilt, with one warning.
  std::vector<fs::path> entries;
  for (const auto& e : fs::recursive_directory_iterator(test::rootOf(dir)))
    if (e.is_regular_file()) entries.push_back(e.path());
  REQUIRE(entries.size() >= 2);
  const std::string a = test::readFile(entries[0]), b = test::readFile(entries[1]);
  { std::ofstream(entries[0], std::ios::binary | std::ios::trunc) << b; }
  { std::ofstream(entries[1], std::ios::binary | std::ios::trunc) << a; }
  BuildStats swapped;
  test::requireIdentical(first, buildPermutations(lib, perms, o, &swapped));
  CHECK(swapped.cacheMismatch == 2);
  CHECK(swapped.compiled == 2);
  REQUIRE(swapped.cacheWarnings.size() == 1);
  CHECK(swapped.cacheWarnings[0].code == "W-CACHE-MISMATCH");
  CHECK(requireAllEntriesValid(cache) == perms.size());
}

TEST_CASE("two concurrent builds on one cache directory give identical output and whole entries", "[cache][build]") {
  test::ScratchDir dir("cache_concurrent");
  const ShaderLibrary& lib = test::shippedLibrary();
  auto perms = cachePermutations();
  BuildOptions o;
  o.targets = {Target::Spirv, Target::Msl};
  o.cacheDir = test::rootOf(dir);
  o.jobs = 2;
  // Load every brick source first: the library's source cache is filled on first use.
  buildPermutations(lib, perms, BuildOptions{});
  std::vector<BuiltPermutation> a, b;
  std::thread other([&] { b = buildPermutations(lib, perms, o); });
  a = buildPermutations(lib, perms, o);
  other.join();
  test::requireIdentical(a, b);
  CHECK(requireAllEntriesValid(ShaderCache(test::rootOf(dir))) == perms.size());
}

TEST_CASE("two concurrent matbricks processes share a cache directory", "[cache][cli]") {
  test::ScratchDir dir("cache_cli");
  const std::string common = (test::sourceDir() / "materials/filament_plastic.json").string() + " " +
                             (test::sourceDir() / "materials/ue4_metal.json").string() +
                             " --lights dir,point --environment sh --targets spirv,glsl450 -q --cache-dir " +
                             (test::rootOf(dir) / "cache").string();  // outputs may not lie inside the cache
  test::CliResult r1, r2;
  std::thread other([&] { r2 = test::runCli("compile " + common + " -o " + (test::rootOf(dir) / "out2").string()); });
  r1 = test::runCli("compile " + common + " -o " + (test::rootOf(dir) / "out1").string());
  other.join();
  INFO(r1.output << r2.output);
  REQUIRE(r1.exitCode == 0);
  REQUIRE(r2.exitCode == 0);
  size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(test::rootOf(dir) / "out1")) {
    if (!e.is_regular_file()) continue;
    const fs::path rel = fs::relative(e.path(), test::rootOf(dir) / "out1");
    INFO(rel);
    CHECK(test::readFile(e.path()) == test::readFile(test::rootOf(dir) / "out2" / rel));
    ++files;
  }
  CHECK(files > 4);
  CHECK(requireAllEntriesValid(ShaderCache(test::rootOf(dir) / "cache")) == 2);
}

TEST_CASE("compile with two entries of its cache directory swapped warns once and writes the right package",
          "[cache][cli]") {
  test::ScratchDir dir("cache_cli_swap");
  const std::string root = test::rootOf(dir).string();
  const std::string compile = "compile " + (test::sourceDir() / "materials/filament_plastic.json").string() + " " +
                              (test::sourceDir() / "materials/ue4_metal.json").string() + " -q --cache-dir " + root +
                              "/cache -o ";
  REQUIRE(test::runCli(compile + root + "/p1").exitCode == 0);
  std::vector<fs::path> entries;
  for (const auto& e : fs::recursive_directory_iterator(root + "/cache"))
    if (e.is_regular_file()) entries.push_back(e.path());
  REQUIRE(entries.size() == 2);
  const std::string a = test::readFile(entries[0]), b = test::readFile(entries[1]);
  { std::ofstream(entries[0], std::ios::binary | std::ios::trunc) << b; }
  { std::ofstream(entries[1], std::ios::binary | std::ios::trunc) << a; }
  auto r = test::runCli(compile + root + "/p2");
  INFO(r.output);
  CHECK(r.exitCode == 0);
  size_t warnings = 0;
  for (size_t at = 0; (at = r.output.find("warning[W-CACHE-MISMATCH]", at)) != std::string::npos; ++at) ++warnings;
  CHECK(warnings == 1);
  CHECK(test::readFile(root + "/p1/manifest.json") == test::readFile(root + "/p2/manifest.json"));
  CHECK(requireAllEntriesValid(ShaderCache(root + "/cache")) == 2);
}

TEST_CASE("the cache key changes with a brick source, an option or the target list", "[cache]") {
  test::ScratchDir root("cache_key_lib");
  fs::copy(test::sourceDir() / "shaderlib", test::rootOf(root), fs::copy_options::recursive);
  auto keyOf = [](const ShaderLibrary& lib, OptimizationLevel level, const std::vector<std::string>& targets) {
    auto perms = test::permutationsOf(test::loadedMaterials(lib, {"filament_plastic"}), {"dir"}, EnvironmentMode::None);
    return buildCacheKey(lib, emitPermutation(lib, perms[0], false, EmitMode::Engine), level, parseTargets(targets));
  };
  ShaderLibrary lib = ShaderLibrary::load(test::rootOf(root));
  const auto O0 = OptimizationLevel::O0, O1 = OptimizationLevel::O1, O2 = OptimizationLevel::O2;
  const std::string base = keyOf(lib, O2, {"spirv"});
  CHECK(base == keyOf(lib, O2, {"spirv"}));
  CHECK(base != keyOf(lib, O0, {"spirv"}));
  CHECK(base != keyOf(lib, O1, {"spirv"}));
  CHECK(keyOf(lib, O0, {"spirv"}) != keyOf(lib, O1, {"spirv"}));
  CHECK(base != keyOf(lib, O2, {"spirv", "hlsl"}));
  CHECK(keyOf(lib, O2, {"spirv", "hlsl", "msl"}) == keyOf(lib, O2, {"msl", "hlsl"}));  // spirv always built

  // A brick the permutation includes changes: a new key, even for a comment-only edit.
  const Brick* brick =
      lib.findBrick(emitPermutation(lib, test::permutationsOf(test::loadedMaterials(lib, {"filament_plastic"}), {"dir"},
                                                              EnvironmentMode::None)[0])
                        .bricks.front());
  REQUIRE(brick);
  { std::ofstream(test::rootOf(root) / brick->file, std::ios::app) << "// edited\n"; }
  ShaderLibrary edited = ShaderLibrary::load(test::rootOf(root));
  CHECK(keyOf(edited, O2, {"spirv"}) != base);
}
