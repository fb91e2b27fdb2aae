// compile: the remote HTTP cache (remote_cache.hpp), on libcurl.
#include "compile/remote_cache.hpp"

#include <curl/curl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <mutex>

#include "core/diagnostics.hpp"
#include "core/input_file.hpp"

namespace mb {

struct RemoteCache::Response {
  CURLcode code = CURLE_OK;
  long status = 0;
  std::string body;
  std::string error;  // curl's message when code != CURLE_OK
};

namespace {

using Response = RemoteCache::Response;

constexpr char kBlobMagic[8] = {'M', 'B', 'R', 'E', 'M', 'O', 'T', '1'};
constexpr size_t kKeyDigits = 32;
// A blob is the magic, the key and one cache entry, which is never larger than a local one
// may be (core/input_file.hpp; the largest shipped permutation with every target is ~1 MB):
// a server that streams more is not serving one of our blobs.
constexpr size_t kMaxBlobBytes = sizeof kBlobMagic + kKeyDigits + input_kind::kCacheEntry.maxBytes;

[[noreturn]] void badUrl(const std::string& url, const std::string& what) {
  throw DiagnosticError({{Severity::Error,
                          "E-CACHE-URL",
                          {RemoteCache::redactUrl(url), 0, 0},
                          what,
                          "give a base URL such as http://cache.example:8080/matbricks"}});
}

size_t appendBody(char* data, size_t size, size_t count, void* user) {
  auto* body = static_cast<std::string*>(user);
  if (body->size() + size * count > kMaxBlobBytes) return 0;  // aborts the transfer
  body->append(data, size * count);
  return size * count;
}

struct Upload {
  const std::string* bytes;
  size_t pos = 0;
};

size_t readUpload(char* dst, size_t size, size_t count, void* user) {
  auto* up = static_cast<Upload*>(user);
  const size_t n = std::min(size * count, up->bytes->size() - up->pos);
  std::memcpy(dst, up->bytes->data() + up->pos, n);
  up->pos += n;
  return n;
}

std::string formatMs(double ms) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f ms", ms);
  return buf;
}

}  // namespace

const std::vector<std::string>& remoteCacheLayouts() {
  static const std::vector<std::string> layouts{"subdirs", "flat", "bazel"};
  return layouts;
}

struct RemoteCache::Handles {
  std::mutex mutex;
  std::vector<CURL*> idle;
  ~Handles() {
    for (CURL* h : idle) curl_easy_cleanup(h);
  }
  CURL* acquire() {
    {
      std::lock_guard lock(mutex);
      if (!idle.empty()) {
        CURL* h = idle.back();
        idle.pop_back();
        return h;
      }
    }
    return curl_easy_init();
  }
  void release(CURL* h) {
    std::lock_guard lock(mutex);
    idle.push_back(h);
  }
};

RemoteCache::RemoteCache(RemoteCacheOptions options) : options_(std::move(options)), handles_(new Handles) {
  const std::string& url = options_.url;
  const size_t scheme = url.find("://");
  if (scheme == std::string::npos || (url.compare(0, scheme, "http") != 0 && url.compare(0, scheme, "https") != 0))
    badUrl(url, "the remote cache URL must start with http:// or https://");
  if (url.size() == scheme + 3 || url[scheme + 3] == '/') badUrl(url, "the remote cache URL names no host");
  if (url.find_first_of(" \t\r\n") != std::string::npos) badUrl(url, "the remote cache URL contains white space");
  bool knownLayout = false;
  for (const auto& l : remoteCacheLayouts()) knownLayout |= l == options_.layout;
  if (!knownLayout) badUrl(url, "unknown remote cache layout '" + options_.layout + "' (subdirs, flat or bazel)");
  if (!(options_.verifyFraction >= 0 && options_.verifyFraction <= 1))
    badUrl(url, "the fraction of remote hits to verify must lie in [0, 1]");
  while (options_.url.size() > scheme + 3 && options_.url.back() == '/') options_.url.pop_back();
  static std::once_flag curlReady;
  std::call_once(curlReady, [] { curl_global_init(CURL_GLOBAL_DEFAULT); });
}

RemoteCache::~RemoteCache() = default;

std::string RemoteCache::blobUrl(const std::string& key) const {
  if (options_.layout == "flat") return options_.url + "/" + key;
  if (options_.layout == "bazel")
    return options_.url + "/ac/" + key + std::string(64 - std::min<size_t>(key.size(), 64), '0');
  return options_.url + "/" + key.substr(0, 2) + "/" + key;
}

std::string RemoteCache::redactUrl(const std::string& url) {
  const size_t scheme = url.find("://");
  if (scheme == std::string::npos) return url.substr(0, url.find_first_of("?#"));
  const size_t hostStart = scheme + 3;
  const size_t pathStart = std::min(url.find_first_of("/?#", hostStart), url.size());
  std::string out = url.substr(0, hostStart);
  const size_t at = url.rfind('@', pathStart == url.size() ? std::string::npos : pathStart);
  const bool userinfo = at != std::string::npos && at >= hostStart && at < pathStart;
  out += userinfo ? "***" + url.substr(at, pathStart - at) : url.substr(hostStart, pathStart - hostStart);
  const size_t tail = std::min(url.find_first_of("?#", pathStart), url.size());
  out += url.substr(pathStart, tail - pathStart);
  if (tail < url.size()) out += url[tail] == '?' ? "?***" : "#***";
  return out;
}

std::string RemoteCache::encodeBlob(const CacheIdentity& identity, const CompiledArtifacts& artifacts) {
  return std::string(kBlobMagic, sizeof kBlobMagic) + identity.key + encodeCacheEntry(identity, artifacts);
}

bool RemoteCache::verifies(const std::string& key) const {
  if (options_.verifyFraction <= 0) return false;
  if (options_.verifyFraction >= 1) return true;
  // The key is a uniform hash: its first 64 bits, as a fraction of 2^64, sample it.
  uint64_t v = 0;
  for (size_t i = 0; i < 16 && i < key.size(); ++i) {
    const char c = key[i];
    v = v * 16 + static_cast<uint64_t>(c >= 'a' ? c - 'a' + 10 : c - '0');
  }
  return static_cast<double>(v) < options_.verifyFraction * 18446744073709551616.0;
}

namespace {

// One request on a pooled handle; `upload` null: GET.
Response perform(CURL* h, const std::string& url, const std::string* upload, double timeoutSeconds) {
  Response r;
  char error[CURL_ERROR_SIZE] = {};
  Upload up{upload};
  curl_easy_reset(h);  // keeps the connection cache; clears the previous request's options
  curl_easy_setopt(h, CURLOPT_URL, url.c_str());
  curl_easy_setopt(h, CURLOPT_NOSIGNAL, 1L);  // worker threads: no SIGALRM for timeouts
  curl_easy_setopt(h, CURLOPT_TIMEOUT_MS, static_cast<long>(timeoutSeconds * 1000));
  curl_easy_setopt(h, CURLOPT_CONNECTTIMEOUT_MS, static_cast<long>(timeoutSeconds * 1000));
  curl_easy_setopt(h, CURLOPT_ERRORBUFFER, error);
  curl_easy_setopt(h, CURLOPT_WRITEFUNCTION, appendBody);
  curl_easy_setopt(h, CURLOPT_WRITEDATA, &r.body);
  curl_slist* headers = nullptr;
  if (upload) {
    curl_easy_setopt(h, CURLOPT_UPLOAD, 1L);
    curl_easy_setopt(h, CURLOPT_READFUNCTION, readUpload);
    curl_easy_setopt(h, CURLOPT_READDATA, &up);
    curl_easy_setopt(h, CURLOPT_INFILESIZE_LARGE, static_cast<curl_off_t>(upload->size()));
    // No "Expect: 100-continue" round trip before large bodies.
    headers = curl_slist_append(headers, "Expect:");
    headers = curl_slist_append(headers, "Content-Type: application/octet-stream");
    curl_easy_setopt(h, CURLOPT_HTTPHEADER, headers);
  }
  r.code = curl_easy_perform(h);
  if (r.code == CURLE_OK)
    curl_easy_getinfo(h, CURLINFO_RESPONSE_CODE, &r.status);
  else
    r.error = error[0] ? error : curl_easy_strerror(r.code);
  curl_slist_free_all(headers);
  return r;
}

}  // namespace

std::string RemoteCache::describe(const std::string& method, const std::string& key, const Response& r) const {
  const std::string where = method + " " + redactUrl(blobUrl(key));
  if (r.code == CURLE_OK) return where + ": HTTP " + std::to_string(r.status);
  // curl's message may quote the URL or the host it was given: never the credentials.
  std::string error = r.error;
  for (size_t at; (at = error.find(options_.url)) != std::string::npos;)
    error.replace(at, options_.url.size(), displayUrl());
  const size_t scheme = options_.url.find("://") + 3;
  const size_t at = options_.url.find('@', scheme);
  if (at != std::string::npos && at < options_.url.find('/', scheme)) {
    const std::string userinfo = options_.url.substr(scheme, at - scheme);
    for (size_t pos; (pos = error.find(userinfo)) != std::string::npos;) error.replace(pos, userinfo.size(), "***");
  }
  return where + ": " + error;
}

void RemoteCache::distrust(const std::string& why) { goOff(why); }

void RemoteCache::noteGet(double ms) {
  std::lock_guard lock(timingMutex_);
  recentGetMs_.push_back(ms);
  if (recentGetMs_.size() > kSlowSamples) recentGetMs_.pop_front();
  offIfSlower();
}

void RemoteCache::noteCompile(double ms) {
  std::lock_guard lock(timingMutex_);
  compileMsSum_ += ms;
  ++compiles_;
  offIfSlower();
}

bool RemoteCache::wantsTimingProbe() {
  std::lock_guard lock(timingMutex_);
  if (probed_ || compiles_ > 0 || off_ || recentGetMs_.size() < kSlowSamples) return false;
  if (*std::min_element(recentGetMs_.begin(), recentGetMs_.end()) <= kProbeMs) return false;
  probed_ = true;
  return true;
}

void RemoteCache::offIfSlower() {
  if (off_ || compiles_ == 0 || recentGetMs_.size() < kSlowSamples) return;
  const double compileMs = compileMsSum_ / static_cast<double>(compiles_);
  if (*std::min_element(recentGetMs_.begin(), recentGetMs_.end()) <= compileMs) return;
  std::string times;
  for (double ms : recentGetMs_) times += (times.empty() ? "" : ", ") + formatMs(ms);
  goOff(displayUrl() + " answers slower than compiling locally (the last " + std::to_string(kSlowSamples) +
        " requests took " + times + "; a local compile takes " + formatMs(compileMs) + " on average)");
}

void RemoteCache::goOff(const std::string& why) {
  std::lock_guard lock(warningMutex_);
  if (warning_.empty()) warning_ = why + "; compiling locally without the remote cache for the rest of this run";
  off_ = true;
}

void RemoteCache::refuseUploads(const std::string& why) {
  std::lock_guard lock(warningMutex_);
  if (warning_.empty()) warning_ = why + "; the remote cache is only read for the rest of this run";
  readOnly_ = true;
}

std::string RemoteCache::warning() const {
  std::lock_guard lock(warningMutex_);
  return warning_;
}

// Until one request has had a good answer, requests go one at a time (the caller holds the
// gate through its verdict): a dead, silent or failing server then costs one request and one
// timeout, not one per worker thread.
std::unique_lock<std::mutex> RemoteCache::firstContactGate() {
  std::unique_lock gate(firstContact_, std::defer_lock);
  if (!reached_) gate.lock();
  return gate;
}

RemoteCache::Response RemoteCache::send(const std::string& url, const std::string* upload) {
  CURL* h = handles_->acquire();
  ++requests_;
  Response r = perform(h, url, upload, options_.timeoutSeconds);
  handles_->release(h);
  return r;
}

RemoteCache::Get RemoteCache::get(const CacheIdentity& identity, CompiledArtifacts& out, std::string* why) {
  auto gate = firstContactGate();
  if (off_) return Get::Unavailable;
  const std::string& key = identity.key;
  const auto t0 = std::chrono::steady_clock::now();
  const Response r = send(blobUrl(key), nullptr);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (r.code != CURLE_OK || (r.status != 200 && r.status != 404)) {
    goOff(describe("GET", key, r));
    return Get::Unavailable;
  }
  reached_ = true;
  noteGet(ms);
  if (r.status == 404) return Get::Miss;
  const std::string& b = r.body;
  if (b.size() < sizeof kBlobMagic + kKeyDigits || std::memcmp(b.data(), kBlobMagic, sizeof kBlobMagic) != 0 ||
      b.compare(sizeof kBlobMagic, kKeyDigits, key) != 0) {
    if (why) *why = redactUrl(blobUrl(key)) + " is not a blob of this key";
    return Get::Corrupt;
  }
  CacheIdentity found;
  const EntryCheck check = decodeCacheEntry(b.substr(sizeof kBlobMagic + kKeyDigits), identity, out, &found);
  if (check == EntryCheck::Ok) return Get::Hit;
  if (why) *why = redactUrl(blobUrl(key)) + " " + describeEntryCheck(check, found);
  return check == EntryCheck::OtherUnit ? Get::OtherUnit : Get::Corrupt;
}

bool RemoteCache::put(const CacheIdentity& identity, const CompiledArtifacts& artifacts) {
  auto gate = firstContactGate();
  if (off_ || readOnly_) return false;
  const std::string url = blobUrl(identity.key);
  const std::string blob = encodeBlob(identity, artifacts);
  const Response r = send(url, &blob);
  if (r.code == CURLE_OK && r.status >= 200 && r.status < 300) {
    reached_ = true;
    return true;
  }
  if (r.code == CURLE_OK && r.status >= 400 && r.status < 500) {
    reached_ = true;  // the server answers; it only refuses to store
    refuseUploads(describe("PUT", identity.key, r));
  } else {
    goOff(describe("PUT", identity.key, r));
  }
  return false;
}

}  // namespace mb
