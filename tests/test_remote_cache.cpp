// The remote HTTP compile cache (compile/remote_cache.hpp) against a real server: nginx with
// WebDAV PUT on 127.0.0.1 (support/dav_server.hpp). Request counts come from the server's
// access log, so "bounded" means an exact number of GETs and PUTs.
#include <catch2/catch.hpp>

#include <fstream>

#include "compile/remote_cache.hpp"
#include "support/build_support.hpp"
#include "support/dav_server.hpp"

using namespace mb;
namespace fs = std::filesystem;

namespace {

std::vector<Permutation> remotePermutations() {
  const auto& mats = test::loadedMaterials(test::shippedLibrary(), {"filament_plastic", "satin_sheen", "ue4_metal"});
  return test::permutationsOf(mats, {"dir", "point"}, EnvironmentMode::Sh);
}

struct RemoteBuild {
  std::vector<BuiltPermutation> built;
  BuildStats stats;
  size_t requests = 0;
};

// One build with a local cache in `localDir` (empty: none) behind the remote cache at `url`.
RemoteBuild buildWithRemote(const std::string& url, const fs::path& localDir, double timeout = 10, double verify = 0,
                            const std::vector<Permutation>& perms = remotePermutations(), unsigned jobs = 2) {
  RemoteCache remote({url, "subdirs", timeout, verify});
  BuildOptions o;
  o.targets = {Target::Spirv, Target::Glsl450};
  o.cacheDir = localDir;
  o.jobs = jobs;
  o.remote = &remote;
  RemoteBuild r;
  r.built = buildPermutations(test::shippedLibrary(), perms, o, &r.stats);
  r.requests = remote.requests();
  return r;
}

// A blob's identity and code (the blob is "MBREMOT1", the key, a cache entry).
CacheIdentity blobIdentity(const std::string& blob, CompiledArtifacts* artifacts = nullptr) {
  CacheIdentity found;
  CompiledArtifacts a;
  REQUIRE(decodeCacheEntry(blob.substr(8 + 32), CacheIdentity{}, a, &found) == EntryCheck::OtherUnit);
  if (artifacts) REQUIRE(decodeCacheEntry(blob.substr(8 + 32), found, *artifacts) == EntryCheck::Ok);
  return found;
}

size_t countOf(const std::vector<Diagnostic>& warnings, const std::string& code) {
  return static_cast<size_t>(
      std::count_if(warnings.begin(), warnings.end(), [&](const Diagnostic& d) { return d.code == code; }));
}

std::vector<fs::path> blobsUnder(const fs::path& root) {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file()) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// A server filled by a build of the default permutations: its 3 blobs, and that build.
struct FilledServer {
  explicit FilledServer(const std::string& name) : dir(name), server(test::rootOf(dir) / "server") {
    clean = buildWithRemote(server.url("cache"), {});
    blobs = blobsUnder(server.root() / "cache");
    REQUIRE(blobs.size() == 3);
  }
  test::ScratchDir dir;
  test::DavServer server;
  RemoteBuild clean;
  std::vector<fs::path> blobs;
};

}  // namespace

TEST_CASE("a remote cache fills on a miss, serves a fresh machine, and the local cache stays in front",
          "[remote-cache][cache]") {
  test::ScratchDir dir("remote_fill");
  test::DavServer server(test::rootOf(dir) / "server");
  const size_t n = remotePermutations().size();

  RemoteBuild first = buildWithRemote(server.url("cache"), test::rootOf(dir) / "local_a");
  CHECK(first.stats.compiled == n);
  CHECK(first.stats.remoteUploads == n);
  CHECK(first.stats.remoteWarning.empty());
  CHECK(server.requestsOnceLogged(int(first.requests)) ==
        std::map<std::string, int>{{"GET 404", int(n)}, {"PUT 201", int(n)}});
  // subdirs layout: <key[0:2]>/<key>, one blob per unit.
  const auto blobs = blobsUnder(server.root() / "cache");
  REQUIRE(blobs.size() == n);
  for (const auto& b : blobs) CHECK(b.parent_path().filename().string() == b.filename().string().substr(0, 2));

  // A second machine: an empty local cache; everything comes from the server, nothing compiles.
  RemoteBuild second = buildWithRemote(server.url("cache"), test::rootOf(dir) / "local_b");
  CHECK(second.stats.compiled == 0);
  CHECK(second.stats.remoteHits == n);
  CHECK(second.stats.remoteUploads == 0);
  test::requireIdentical(first.built, second.built);
  CHECK(server.requestsOnceLogged(int(first.requests + second.requests))["GET 200"] == int(n));

  // The same machine again: the local cache answers, the server sees no request.
  const int before = server.total();
  RemoteBuild third = buildWithRemote(server.url("cache"), test::rootOf(dir) / "local_b");
  CHECK(third.requests == 0);
  CHECK(server.total() == before);
  test::requireIdentical(first.built, third.built);
}

TEST_CASE("a corrupt, truncated or misplaced remote blob is detected, ignored and replaced", "[remote-cache][cache]") {
  test::ScratchDir dir("remote_corrupt");
  test::DavServer server(test::rootOf(dir) / "server");
  RemoteBuild clean = buildWithRemote(server.url("cache"), {});
  const auto blobs = blobsUnder(server.root() / "cache");
  REQUIRE(blobs.size() == 3);
  std::string flipped = test::readFile(blobs[0]);
  flipped[flipped.size() / 2] ^= 0x20;
  std::ofstream(blobs[0], std::ios::binary | std::ios::trunc) << flipped;
  const std::string whole = test::readFile(blobs[1]);
  std::ofstream(blobs[1], std::ios::binary | std::ios::trunc) << whole.substr(0, whole.size() - 100);
  // A whole, valid blob, but of another key: its key check fails.
  std::ofstream(blobs[2], std::ios::binary | std::ios::trunc) << whole;

  RemoteBuild repaired = buildWithRemote(server.url("cache"), {});
  CHECK(repaired.stats.remoteCorrupt == 3);
  CHECK(repaired.stats.compiled == 3);
  CHECK(repaired.stats.remoteUploads == 3);  // the rebuilt blobs replace the bad ones
  CHECK(repaired.stats.remoteWarning.empty());
  test::requireIdentical(clean.built, repaired.built);

  RemoteBuild after = buildWithRemote(server.url("cache"), {});
  CHECK(after.stats.remoteHits == 3);
  CHECK(after.stats.compiled == 0);
}

TEST_CASE("a remote cache that is down or silent costs one request and one warning", "[remote-cache][cache]") {
  test::ScratchDir dir("remote_down");
  const test::SilentServer silent;
  RemoteBuild reference = buildWithRemote(silent.url(), {}, 0.2);  // compiles everything
  CHECK(reference.requests == 1);
  CHECK(reference.stats.compiled == 3);
  CHECK(reference.stats.remoteWarning.find("timed out") != std::string::npos);
  CHECK(reference.stats.remoteWarning.find("compiling locally") != std::string::npos);

  const int port = test::unusedLocalPort();
  RemoteBuild down = buildWithRemote("http://127.0.0.1:" + std::to_string(port) + "/cache", {});
  CHECK(down.requests == 1);
  CHECK(down.stats.compiled == 3);
  CHECK(down.stats.remoteUploads == 0);
  CHECK(!down.stats.remoteWarning.empty());
  test::requireIdentical(reference.built, down.built);
}

TEST_CASE("a remote cache that refuses uploads is still read", "[remote-cache][cache]") {
  test::ScratchDir dir("remote_readonly");
  test::DavServer server(test::rootOf(dir) / "server");
  // Fill one blob through the writable location, then use the read-only one.
  RemoteBuild filled = buildWithRemote(server.url("cache"), {});
  fs::remove(blobsUnder(server.root() / "cache").front());
  const auto before = server.requests();
  RemoteBuild readOnly = buildWithRemote(server.url("ro/cache"), {});
  CHECK(readOnly.stats.remoteHits == 2);
  CHECK(readOnly.stats.compiled == 1);
  CHECK(readOnly.stats.remoteUploads == 0);
  CHECK(readOnly.stats.remoteWarning.find("HTTP 405") != std::string::npos);
  CHECK(readOnly.stats.remoteWarning.find("only read") != std::string::npos);
  auto after = server.requests();
  auto added = [&](const std::string& what) { return after[what] - (before.count(what) ? before.at(what) : 0); };
  // nginx logs the refused PUT only once it has drained the request body, which can be after
  // the client read the 405 and went on (seen under load with the larger entries that carry
  // a fragment shader): wait for the line, for up to 5 s.
  for (int i = 0; i < 500 && added("PUT 405") == 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    after = server.requests();
  }
  CHECK(added("PUT 405") == 1);
  CHECK(added("GET 200") == 2);
  CHECK(added("GET 404") == 1);
  test::requireIdentical(filled.built, readOnly.built);
}

TEST_CASE("the bazel and flat layouts put blobs where those servers expect them", "[remote-cache]") {
  RemoteCache bazel({"http://h:1/c/", "bazel", 1}), flat({"https://h/c", "flat", 1}),
      subdirs({"http://h", "subdirs", 1});
  const std::string key = "0123456789abcdef0123456789abcdef";
  CHECK(bazel.blobUrl(key) == "http://h:1/c/ac/" + key + std::string(32, '0'));
  CHECK(flat.blobUrl(key) == "https://h/c/" + key);
  CHECK(subdirs.blobUrl(key) == "http://h/01/" + key);
  for (const char* bad : {"ftp://h/c", "h/c", "http://", "http:///c", "http://h/a b"})
    CHECK_THROWS_AS(RemoteCache({bad, "subdirs", 1}), DiagnosticError);
  CHECK_THROWS_AS(RemoteCache({"http://h", "nested", 1}), DiagnosticError);
}

TEST_CASE("concurrent matbricks processes writing one remote cache leave only whole blobs", "[remote-cache][cli]") {
  test::ScratchDir dir("remote_concurrent");
  test::DavServer server(test::rootOf(dir) / "server");
  const std::string root = test::rootOf(dir).string(),
                    scene = (test::sourceDir() / "examples/scenes/showroom.json").string();
  const std::string compile = std::string(std::getenv("MATBRICKS_CLI")) + " compile -q -j 1 --scene " + scene +
                              " --cache-url " + server.url("cache");
  // Two processes, two empty local caches, one server, started together; each exit status
  // is kept in a file.
  auto one = [&](const std::string& n) {
    return "(" + compile + " --cache-dir " + root + "/l" + n + " -o " + root + "/p" + n + " > " + root + "/out" + n +
           " 2>&1; echo $? > " + root + "/rc" + n + ")";
  };
  REQUIRE(std::system((one("1") + " & " + one("2") + " & wait").c_str()) == 0);
  for (const char* n : {"1", "2"}) {
    INFO(test::readFile(root + "/out" + n));
    CHECK(test::readFile(root + "/rc" + n) == "0\n");
    CHECK(test::readFile(root + "/out" + n).find("W-CACHE-REMOTE") == std::string::npos);
  }
  for (const auto& e : fs::recursive_directory_iterator(root + "/p1"))
    if (e.is_regular_file())
      CHECK(test::readFile(e.path()) == test::readFile(root + "/p2/" + fs::relative(e.path(), root + "/p1").string()));
  // Every blob on the server is whole: a third machine compiles nothing.
  auto third = test::runCli("compile --scene " + scene + " --cache-url " + server.url("cache") + " --cache-dir " +
                            root + "/l3 -o " + root + "/p3");
  INFO(third.output);
  REQUIRE(third.exitCode == 0);
  CHECK(third.output.find("0 compiled") != std::string::npos);
  CHECK(third.output.find("0 uploaded") != std::string::npos);
}

TEST_CASE("compile --cache-url: usage errors exit 2; a dead server warns once and the build succeeds",
          "[remote-cache][cli]") {
  test::ScratchDir dir("remote_cli");
  test::bypassProxyForLocalhost();
  const std::string root = test::rootOf(dir).string();
  const std::string mat = (test::sourceDir() / "materials/ue4_metal.json").string();
  auto bad = test::runCli("compile " + mat + " --cache-url ftp://x/y -o " + root + "/p");
  CHECK(bad.exitCode == 2);
  CHECK(bad.output.find("http:// or https://") != std::string::npos);
  CHECK(test::runCli("compile " + mat + " --cache-url http://x --no-cache -o " + root + "/p").exitCode == 2);
  CHECK(test::runCli("compile " + mat + " --cache-url http://x --cache-url-layout nested -o " + root + "/p").exitCode ==
        2);
  CHECK(test::runCli("compile " + mat + " --cache-url http://x --cache-verify 1.5 -o " + root + "/p").exitCode == 2);
  CHECK(test::runCli("compile " + mat + " --no-cache --cache-verify 0.5 -o " + root + "/p").exitCode == 2);
  CHECK(!fs::exists(root + "/p"));

  auto down = test::runCli("compile " + mat + " --no-cache -o " + root + "/p");  // reference
  REQUIRE(down.exitCode == 0);
  auto r = test::runCli("compile " + mat + " --cache-dir " + root + "/l -o " + root +
                        "/q --cache-url http://127.0.0.1:" + std::to_string(test::unusedLocalPort()) + "/c");
  INFO(r.output);
  CHECK(r.exitCode == 0);
  size_t warnings = 0;
  for (size_t at = 0; (at = r.output.find("W-CACHE-REMOTE", at)) != std::string::npos; ++at) ++warnings;
  CHECK(warnings == 1);
  CHECK(test::readFile(root + "/p/manifest.json") == test::readFile(root + "/q/manifest.json"));
}

TEST_CASE("shards of a build farm share one remote cache: a fresh machine then compiles nothing",
          "[remote-cache][shards][cli]") {
  test::ScratchDir dir("remote_shards");
  test::DavServer server(test::rootOf(dir) / "server");
  const std::string root = test::rootOf(dir).string(),
                    scene = (test::sourceDir() / "examples/scenes/showroom.json").string();
  const std::string remote = " --cache-url " + server.url("cache");
  for (const char* i : {"1", "2", "3"}) {
    auto r = test::runCli("compile -q --scene " + scene + remote + " --shard " + i + "/3 --cache-dir " + root + "/l" +
                          i + " -o " + root + "/s" + i);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
  }
  const auto filled = server.requests();
  auto whole = test::runCli("compile --scene " + scene + remote + " --cache-dir " + root + "/l4 -o " + root + "/p");
  INFO(whole.output);
  REQUIRE(whole.exitCode == 0);
  CHECK(whole.output.find(" 0 compiled, 10 cached, 10 of them from the remote cache, 0 uploaded") != std::string::npos);
  int filledTotal = 0;
  for (const auto& [what, count] : filled) filledTotal += count;
  auto after = server.requestsOnceLogged(filledTotal + 10);
  CHECK(after["GET 200"] == 10);
  CHECK(after["PUT 201"] == filled.at("PUT 201"));
  // And it equals the merge of the same shards.
  REQUIRE(test::runCli("merge -q " + root + "/s1 " + root + "/s2 " + root + "/s3 -o " + root + "/m").exitCode == 0);
  for (const auto& e : fs::recursive_directory_iterator(root + "/p"))
    if (e.is_regular_file())
      CHECK(test::readFile(e.path()) == test::readFile(root + "/m/" + fs::relative(e.path(), root + "/p").string()));
}

TEST_CASE("another unit's blob with its key field rewritten is a miss: rebuilt, never stored locally, one warning",
          "[remote-cache][cache]") {
  FilledServer filled("remote_other_unit");
  const auto& [dir, server, clean, blobs] = filled;
  // What a confused or hostile server answers: blob 1's real bytes, its key field made blob 0's.
  const std::string victimKey = blobs[0].filename().string();
  std::string doctored = test::readFile(blobs[1]);
  doctored.replace(8, 32, victimKey);
  std::ofstream(blobs[0], std::ios::binary | std::ios::trunc) << doctored;

  const fs::path local = test::rootOf(dir) / "local";
  RemoteBuild fooled = buildWithRemote(server.url("cache"), local);
  CHECK(fooled.stats.remoteMismatch == 1);
  CHECK(fooled.stats.remoteCorrupt == 0);
  CHECK(fooled.stats.remoteHits == 2);
  CHECK(fooled.stats.compiled == 1);
  CHECK(fooled.stats.remoteUploads == 1);  // the rebuilt blob replaces the doctored one
  test::requireIdentical(clean.built, fooled.built);
  REQUIRE(countOf(fooled.stats.cacheWarnings, "W-CACHE-REMOTE-MISMATCH") == 1);
  for (const auto& w : fooled.stats.cacheWarnings)
    if (w.code == "W-CACHE-REMOTE-MISMATCH") CHECK(w.message.find(victimKey) != std::string::npos);

  // The local cache holds the rebuilt entry, not the doctored one: a build with no remote is right.
  BuildOptions o;
  o.targets = {Target::Spirv, Target::Glsl450};
  o.cacheDir = local;
  BuildStats alone;
  test::requireIdentical(clean.built, buildPermutations(test::shippedLibrary(), remotePermutations(), o, &alone));
  CHECK(alone.cacheHits == 3);
  CHECK(alone.cacheMismatch == 0);
}

TEST_CASE("cache verification: a valid-looking wrong entry under the right key is caught and evicted",
          "[remote-cache][cache]") {
  FilledServer filled("remote_verify");
  const auto& [dir, server, clean, blobs] = filled;
  // A forger who rewrites every identity field and the hashes: blob 1's code under blob 0's identity.
  CompiledArtifacts otherCode;
  blobIdentity(test::readFile(blobs[1]), &otherCode);
  const CacheIdentity victim = blobIdentity(test::readFile(blobs[0]));
  std::ofstream(blobs[0], std::ios::binary | std::ios::trunc) << RemoteCache::encodeBlob(victim, otherCode);

  // Without verification the key is taken as proof (docs/targets.md): the forgery is believed.
  RemoteBuild believed = buildWithRemote(server.url("cache"), {});
  CHECK(believed.stats.remoteHits == 3);
  size_t differing = 0;
  for (size_t i = 0; i < clean.built.size(); ++i) differing += clean.built[i].spirvHash != believed.built[i].spirvHash;
  CHECK(differing == 1);

  // Verifying a fraction that samples the forged unit only (blobs are sorted by key, and a key
  // is sampled when its first 64 bits, as a fraction of 2^64, lie below the fraction): the
  // build fails with E-CACHE-VERIFY, and the two unverified hits are evicted from the local cache.
  auto sampleValue = [](const fs::path& blob) {
    return static_cast<double>(std::stoull(blob.filename().string().substr(0, 16), nullptr, 16)) / 0x1p64;
  };
  const double fraction = (sampleValue(blobs[0]) + sampleValue(blobs[1])) / 2;
  const fs::path local = test::rootOf(dir) / "local";
  try {
    buildWithRemote(server.url("cache"), local, 10, fraction);
    FAIL("the forged entry was believed");
  } catch (const DiagnosticError& e) {
    REQUIRE(e.diagnostics().size() == 1);
    CHECK(e.diagnostics()[0].code == "E-CACHE-VERIFY");
  }
  size_t left = 0;
  if (fs::exists(local))
    for (const auto& e : fs::recursive_directory_iterator(local)) left += e.is_regular_file();
  CHECK(left == 0);

  // Verified and equal: counted, and the build is the clean one.
  fs::remove(blobs[0]);
  RemoteBuild verified = buildWithRemote(server.url("cache"), {}, 10, 1.0);
  CHECK(verified.stats.remoteVerified == 2);
  CHECK(verified.stats.compiled == 1);
  test::requireIdentical(clean.built, verified.built);
}

TEST_CASE("cache verification samples by key: the same keys every run, about the given fraction", "[remote-cache]") {
  RemoteCache half({"http://h", "subdirs", 1, 0.5}), none({"http://h", "subdirs", 1, 0}),
      all({"http://h", "subdirs", 1, 1});
  size_t sampled = 0;
  const size_t n = 2000;
  for (size_t i = 0; i < n; ++i) {
    const std::string key = ShaderCache::key({std::to_string(i)});
    sampled += half.verifies(key);
    CHECK(half.verifies(key) == half.verifies(key));
    CHECK(!none.verifies(key));
    CHECK(all.verifies(key));
  }
  // Binomial(2000, 0.5): standard deviation 22.4; 5 of them either side.
  CHECK(sampled > n / 2 - 112);
  CHECK(sampled < n / 2 + 112);
  CHECK_THROWS_AS(RemoteCache({"http://h", "subdirs", 1, 1.5}), DiagnosticError);
}

TEST_CASE("credentials in the cache URL never appear in a message", "[remote-cache][cli]") {
  CHECK(RemoteCache::redactUrl("http://user:secret@host:8080/c/d?token=abc") == "http://***@host:8080/c/d?***");
  CHECK(RemoteCache::redactUrl("https://tok@host") == "https://***@host");
  CHECK(RemoteCache::redactUrl("http://host/c#frag") == "http://host/c#***");
  CHECK(RemoteCache::redactUrl("http://host/a@b") == "http://host/a@b");  // an @ in the path is no userinfo
  RemoteCache remote({"http://user:secret@127.0.0.1:1/c", "subdirs", 1});
  CHECK(remote.displayUrl() == "http://***@127.0.0.1:1/c");

  test::ScratchDir dir("remote_secret");
  test::bypassProxyForLocalhost();
  const std::string root = test::rootOf(dir).string();
  const std::string mat = (test::sourceDir() / "materials/ue4_metal.json").string();
  const std::string url =
      "http://alice9:s3cr3t@127.0.0.1:" + std::to_string(test::unusedLocalPort()) + "/c?token=t0k3n";
  auto r = test::runCli("compile " + mat + " --cache-dir " + root + "/l -o " + root + "/p --cache-url '" + url + "'");
  INFO(r.output);
  CHECK(r.exitCode == 0);
  CHECK(r.output.find("W-CACHE-REMOTE") != std::string::npos);
  CHECK(r.output.find("***@127.0.0.1") != std::string::npos);
  auto bad = test::runCli("compile " + mat + " -o " + root + "/q --cache-url 'ftp://alice9:s3cr3t@h/c?token=t0k3n'");
  INFO(bad.output);
  CHECK(bad.exitCode == 2);
  for (const auto* out : {&r.output, &bad.output}) {
    CHECK(out->find("s3cr3t") == std::string::npos);
    CHECK(out->find("t0k3n") == std::string::npos);
    CHECK(out->find("alice9") == std::string::npos);
  }
}

TEST_CASE("a remote cache slower than compiling locally is noticed and dropped", "[remote-cache][cache]") {
  // Five materials, one unit each, built one at a time so that the requests come in a known order.
  const auto& mats = test::loadedMaterials(
      test::shippedLibrary(), {"filament_plastic", "satin_sheen", "ue4_metal", "brushed_metal", "worn_car_paint"});
  const auto perms = test::permutationsOf(mats, {"dir"}, EnvironmentMode::None);
  // The delay is derived from this machine's compile time of these units, so that every
  // answer is slower than compiling whatever the machine's speed (and slower than the probe
  // threshold); the timeout leaves it room.
  BuildOptions plain;
  plain.targets = {Target::Spirv, Target::Glsl450};
  plain.jobs = 1;
  BuildStats measured;
  double compileMs = 0;
  for (const auto& b : buildPermutations(test::shippedLibrary(), perms, plain, &measured)) compileMs += b.compileMs;
  REQUIRE(measured.units == 5);
  compileMs /= 5;
  const auto delay = std::chrono::milliseconds(static_cast<long>(std::max(3 * compileMs, 2 * RemoteCache::kProbeMs)));
  const double timeout = 2.0 * static_cast<double>(delay.count()) / 1000 + 1;
  test::SlowServer server(delay);

  // Every answer a slow miss: GET, compile, PUT for two units; the third GET makes the last
  // three all slower than the mean compile, and the cache goes off: 3 GETs and 2 PUTs of 10.
  RemoteBuild misses = buildWithRemote(server.url(), {}, timeout, 0, perms, 1);
  INFO(misses.stats.remoteWarning);
  CHECK(server.requests() == std::map<std::string, int>{{"GET 404", 3}, {"PUT 201", 2}});
  CHECK(misses.stats.compiled == 5);
  CHECK(misses.stats.remoteWarning.find("slower than compiling locally") != std::string::npos);
  CHECK(countOf(misses.stats.cacheWarnings, "W-CACHE-REMOTE") == 1);

  // Every answer a slow hit: no local compile to compare with, so after three slow hits one
  // unit is compiled as a probe; the cache then goes off and the rest compile here.
  server.setDelay(std::chrono::milliseconds(0));
  RemoteBuild fill = buildWithRemote(server.url(), {}, timeout, 0, perms, 1);
  CHECK(fill.stats.remoteWarning.empty());
  CHECK(server.requests()["PUT 201"] == 2 + 3);
  server.setDelay(delay);
  const int before = server.total();
  RemoteBuild hits = buildWithRemote(server.url(), {}, timeout, 0, perms, 1);
  INFO(hits.stats.remoteWarning);
  CHECK(server.total() - before == 3);
  CHECK(hits.stats.remoteHits == 3);
  CHECK(hits.stats.compiled == 2);
  CHECK(hits.stats.remoteWarning.find("slower than compiling locally") != std::string::npos);
  test::requireIdentical(misses.built, hits.built);
}
