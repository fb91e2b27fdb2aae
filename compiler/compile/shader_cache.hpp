// compile: a content-addressed on-disk cache of compiled permutations (docs/targets.md
// "Cache"). The key covers everything that affects the output: the emitted GLSL (which holds
// every brick's source verbatim), the brick source files' own hashes, the compile options and
// targets, the matbricks version, and the glslang, SPIRV-Tools and SPIRV-Cross versions.
//
// Safe for concurrent invocations: an entry is written to a unique temporary file in the
// cache directory and renamed into place, so a reader sees either no entry or a whole one.
// Every entry carries a hash of its payload; an entry that fails the check (truncated,
// edited, wrong format) is reported as corrupt, ignored and rebuilt. Every entry also carries
// what it was built from (CacheIdentity), checked against what the build asked for on every
// use: an intact entry of another unit (two files swapped, a blob stored under another key)
// is a mismatch, evicted and rebuilt, never believed.
#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mb {

// One compiled shader stage.
struct StageArtifacts {
  std::vector<uint32_t> spirv;
  std::map<std::string, std::string> targets;  // target -> text, for every non-spirv target
  nlohmann::json reflection;                   // reflectSpirv(spirv)
};

// Everything one permutation compiles to: the kernel (this object's own StageArtifacts) and
// its fragment shader (docs/fragment-stage.md; empty when the build made none).
struct CompiledArtifacts : StageArtifacts {
  StageArtifacts fragment;
  // "hlsl" / "msl" -> the engine include's body, when that target was asked for
  // (engine_includes.hpp crossCompileIncludes).
  std::map<std::string, std::string> includes;
};

// What an entry was built from: the unit's cache key and a digest of the GLSL texts it
// compiles (kernel, fragment and their mediump forms). The build recomputes both from its
// plan, so an entry is used only for the unit whose code it holds. This detects mistakes
// (swapped or misfiled entries, a blob under another key), not forgery: anyone who can write
// a cache can also write these fields (docs/targets.md "What a remote cache is trusted for").
struct CacheIdentity {
  std::string key;     // ShaderCache::key of the unit (32 hex digits)
  std::string source;  // ShaderCache::key over the unit's GLSL texts
  bool operator==(const CacheIdentity&) const = default;
};

// The bytes of one cache entry (format in shader_cache.cpp), as stored on disk, in a shard
// directory (compile/shard.hpp) and, wrapped, in a remote cache (compile/remote_cache.hpp).
std::string encodeCacheEntry(const CacheIdentity& identity, const CompiledArtifacts& artifacts);
// Whether an entry's bytes may be used for the unit `expected`.
enum class EntryCheck {
  Ok,         // a whole, intact entry of this unit
  Damaged,    // not a whole, intact entry of this format (truncated, edited, other version)
  OtherUnit,  // a whole, intact entry, but built from another unit
};
// `out` is set only for Ok; `found` (if given) gets the entry's identity for Ok and OtherUnit.
EntryCheck decodeCacheEntry(const std::string& bytes, const CacheIdentity& expected, CompiledArtifacts& out,
                            CacheIdentity* found = nullptr);
// Message text for a check that failed, e.g. "holds the entry of another unit (key ...)".
std::string describeEntryCheck(EntryCheck check, const CacheIdentity& found);

class ShaderCache {
 public:
  // An empty dir disables the cache (every lookup misses, store does nothing).
  explicit ShaderCache(std::filesystem::path dir);
  // The default directory: $MATBRICKS_CACHE_DIR, else $XDG_CACHE_HOME/matbricks, else
  // ~/.cache/matbricks.
  static std::filesystem::path defaultDir();

  bool enabled() const { return !dir_.empty(); }
  const std::filesystem::path& dir() const { return dir_; }
  // Version of the entry format and of the key's recipe; part of every key (build.cpp).
  // 2: + the fragment shader and the HLSL/MSL includes
  // 3: + the entry's CacheIdentity
  static constexpr const char* kFormatVersion = "matbricks-cache-3";
  // 32 hex digits (XXH3-128) over the given parts, each length-prefixed.
  static std::string key(const std::vector<std::string>& parts);
  // The identity of a unit keyed `key` that compiles `sources` (its GLSL texts, in a fixed order).
  static CacheIdentity identity(const std::string& key, const std::vector<std::string>& sources);

  enum class Lookup {
    Hit,
    Miss,        // no entry
    Corrupt,     // damaged (EntryCheck::Damaged)
    OtherUnit,   // an intact entry of another unit at this key's path
    Unreadable,  // not a regular file (a symlink to a device, a FIFO, a directory), too large or unreadable
  };
  // Thread-safe. Entries are read through core/input_file.hpp (regular files, bounded size).
  // On Corrupt, OtherUnit and Unreadable the entry is evicted (and rebuilt by the caller);
  // `why` (if given) says what was wrong, naming the file.
  Lookup load(const CacheIdentity& identity, CompiledArtifacts& out, std::string* why = nullptr) const;
  // Thread-safe; failures to write (read-only dir, full disk) are not errors: the build goes
  // on uncached, and the return value says so.
  bool store(const CacheIdentity& identity, const CompiledArtifacts& artifacts) const;
  // Removes a key's entry, if any (entries a remote cache supplied that proved untrustworthy).
  void evict(const std::string& key) const;
  // Path of an entry (for tests that corrupt one on purpose): <dir>/<key[0:2]>/<key>.mbc.
  std::filesystem::path entryPath(const std::string& key) const;

 private:
  std::filesystem::path dir_;
};

}  // namespace mb
