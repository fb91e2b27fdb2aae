// compile: a remote compile cache over plain HTTP (docs/targets.md "Remote cache"), the
// protocol of Bazel's HTTP remote cache and ccache's HTTP storage: GET a key's blob (200 or
// 404), PUT it after a compile. Any server that speaks it works: bazel-remote, nginx with
// WebDAV PUT, an object store's HTTP API. The local ShaderCache stays in front of it.
//
// A blob is "MBREMOT1", the 32-digit key, then a local cache entry (encodeCacheEntry, which
// carries the unit's CacheIdentity), so a truncated, edited or misplaced blob fails its own
// hash, key or identity check and is ignored. Unreachable, failing or slow (past the
// timeout): the first failure is kept as a warning and the remote cache is off for the rest
// of the run, so a dead server costs one timeout, not one per permutation. A server that
// answers, but slower than compiling locally, is turned off too (noteCompile). A server that
// refuses uploads (403, 405, ...) is only read. Messages never show the URL's user name,
// password or query (redactUrl).
#pragma once
#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "compile/shader_cache.hpp"

namespace mb {

struct RemoteCacheOptions {
  std::string url;  // http:// or https://; empty: no remote cache
  // Where a key's blob lives under the URL, as ccache names its HTTP layouts:
  //   subdirs  URL/<key[0:2]>/<key>   (default)
  //   flat     URL/<key>
  //   bazel    URL/ac/<key, zero-padded to 64 hex digits>   (Bazel's action-cache path)
  std::string layout = "subdirs";
  double timeoutSeconds = 10;  // per request, connection included
  // --cache-verify: the fraction of remote hits to compile locally and compare byte for byte
  // (sampled by key, so the same units every run); 0: none, 1: every hit.
  double verifyFraction = 0;
};

// The layouts above, for the command line's check.
const std::vector<std::string>& remoteCacheLayouts();

class RemoteCache {
 public:
  // Throws DiagnosticError E-CACHE-URL for a URL that is not http(s)://host... or an unknown
  // layout. Nothing is contacted here.
  explicit RemoteCache(RemoteCacheOptions options);
  ~RemoteCache();
  RemoteCache(const RemoteCache&) = delete;
  RemoteCache& operator=(const RemoteCache&) = delete;

  enum class Get {
    Hit,
    Miss,
    Corrupt,      // truncated, edited, another format, or filed under another key
    OtherUnit,    // an intact entry of another unit (decodeCacheEntry's OtherUnit)
    Unavailable,  // the cache is off (see above)
  };
  struct Response;  // of one HTTP request (remote_cache.cpp)
  // Thread-safe. On Corrupt and OtherUnit, `why` (if given) says what was wrong.
  Get get(const CacheIdentity& identity, CompiledArtifacts& out, std::string* why = nullptr);
  // Thread-safe; true if the server accepted the blob.
  bool put(const CacheIdentity& identity, const CompiledArtifacts& artifacts);

  // The URL of a key's blob (requests and tests; it may hold credentials: never print it).
  std::string blobUrl(const std::string& key) const;
  // The base URL as messages show it (redactUrl).
  std::string displayUrl() const { return redactUrl(options_.url); }
  // `url` without its user name and password, query or fragment:
  // "http://user:secret@host/c?token=x" -> "http://***@host/c?***".
  static std::string redactUrl(const std::string& url);
  // The blob bytes for a unit (tests doctor them on purpose).
  static std::string encodeBlob(const CacheIdentity& identity, const CompiledArtifacts& artifacts);

  // Whether this key's remote hit is one --cache-verify compiles and compares.
  bool verifies(const std::string& key) const;
  // A remote hit that a local compile contradicted: the cache is off for the rest of the run.
  void distrust(const std::string& why);
  // A unit compiled locally in `ms`. Compared with the GETs' times: once each of the last
  // kSlowSamples GETs took longer than the mean local compile, the cache is off (a warning).
  void noteCompile(double ms);
  // True (once per run) when no local compile has been timed yet and the last kSlowSamples
  // GETs each took over kProbeMs: the caller then compiles one unit without asking the
  // remote, so that a remote that always hits, but slowly, is noticed too.
  bool wantsTimingProbe();
  static constexpr size_t kSlowSamples = 3;
  // Far slower than a cache on the same network answers (a few ms), and faster than any
  // unit compiles (the smallest takes tens of ms, docs/targets.md "Measured costs").
  static constexpr double kProbeMs = 100;

  // The first failure ("" if none): what made the cache go off, or refuse uploads.
  std::string warning() const;
  // Requests sent so far (hits, misses and uploads are counted per unit in BuildStats).
  size_t requests() const { return requests_; }

 private:
  struct Handles;  // a pool of libcurl easy handles (connections are reused)
  std::unique_lock<std::mutex> firstContactGate();
  Response send(const std::string& url, const std::string* upload);  // upload null: GET
  std::string describe(const std::string& method, const std::string& key, const Response& r) const;
  void goOff(const std::string& why);
  void refuseUploads(const std::string& why);
  void noteGet(double ms);
  void offIfSlower();  // with timingMutex_ held

  RemoteCacheOptions options_;
  std::mutex timingMutex_;
  std::deque<double> recentGetMs_;  // the last kSlowSamples answered GETs
  double compileMsSum_ = 0;
  size_t compiles_ = 0;
  bool probed_ = false;
  std::unique_ptr<Handles> handles_;
  std::atomic<bool> off_{false}, readOnly_{false}, reached_{false};
  std::mutex firstContact_;
  std::atomic<size_t> requests_{0};
  mutable std::mutex warningMutex_;
  std::string warning_;
};

}  // namespace mb
