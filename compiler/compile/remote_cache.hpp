// compile: a remote compile cache over plain HTTP (docs/targets.md "Remote cache"), the
// protocol of Bazel's HTTP remote cache and ccache's HTTP storage: GET a key's blob (200 or
// 404), PUT it after a compile. Any server that speaks it works: bazel-remote, nginx with
// WebDAV PUT, an object store's HTTP API. The local ShaderCache stays in front of it.
//
// A blob is "MBREMOT1", the 32-digit key, then a local cache entry (encodeCacheEntry), so a
// truncated, edited or misplaced blob fails its own hash or key check and is ignored.
// Unreachable, failing or slow (past the timeout): the first failure is kept as a warning
// and the remote cache is off for the rest of the run, so a dead server costs one timeout,
// not one per permutation. A server that refuses uploads (403, 405, ...) is only read.
#pragma once
#include <atomic>
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

  enum class Get { Hit, Miss, Corrupt, Unavailable };
  struct Response;  // of one HTTP request (remote_cache.cpp)
  // Thread-safe. Unavailable once the cache is off (see above).
  Get get(const std::string& key, CompiledArtifacts& out);
  // Thread-safe; true if the server accepted the blob.
  bool put(const std::string& key, const CompiledArtifacts& artifacts);

  // The URL of a key's blob (tests, and the warning text).
  std::string blobUrl(const std::string& key) const;
  // The blob bytes for a key (tests corrupt them on purpose).
  static std::string encodeBlob(const std::string& key, const CompiledArtifacts& artifacts);

  // The first failure ("" if none): what made the cache go off, or refuse uploads.
  std::string warning() const;
  // Requests sent so far (hits, misses and uploads are counted per unit in BuildStats).
  size_t requests() const { return requests_; }

 private:
  struct Handles;  // a pool of libcurl easy handles (connections are reused)
  std::unique_lock<std::mutex> firstContactGate();
  Response send(const std::string& url, const std::string* upload);  // upload null: GET
  void goOff(const std::string& why);
  void refuseUploads(const std::string& why);

  RemoteCacheOptions options_;
  std::unique_ptr<Handles> handles_;
  std::atomic<bool> off_{false}, readOnly_{false}, reached_{false};
  std::mutex firstContact_;
  std::atomic<size_t> requests_{0};
  mutable std::mutex warningMutex_;
  std::string warning_;
};

}  // namespace mb
