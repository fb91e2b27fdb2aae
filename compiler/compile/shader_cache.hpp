// compile: a content-addressed on-disk cache of compiled permutations (docs/targets.md
// "Cache"). The key covers everything that affects the output: the emitted GLSL (which holds
// every brick's source verbatim), the brick source files' own hashes, the compile options and
// targets, the matbricks version, and the glslang, SPIRV-Tools and SPIRV-Cross versions.
//
// Safe for concurrent invocations: an entry is written to a unique temporary file in the
// cache directory and renamed into place, so a reader sees either no entry or a whole one.
// Every entry carries a hash of its payload; an entry that fails the check (truncated,
// edited, wrong format) is reported as corrupt, ignored and rebuilt.
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

// The bytes of one cache entry (format in shader_cache.cpp), as stored on disk, in a shard
// directory (compile/shard.hpp) and, wrapped, in a remote cache (compile/remote_cache.hpp).
std::string encodeCacheEntry(const CompiledArtifacts& artifacts);
// False, leaving `out` untouched, for anything but a whole, intact entry of this format.
bool decodeCacheEntry(const std::string& bytes, CompiledArtifacts& out);

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
  static constexpr const char* kFormatVersion = "matbricks-cache-2";
  // 32 hex digits (XXH3-128) over the given parts, each length-prefixed.
  static std::string key(const std::vector<std::string>& parts);

  enum class Lookup { Hit, Miss, Corrupt };
  // Thread-safe. On Corrupt the entry is deleted (and will be rebuilt by the caller).
  Lookup load(const std::string& key, CompiledArtifacts& out) const;
  // Thread-safe; failures to write (read-only dir, full disk) are not errors: the build goes
  // on uncached, and the return value says so.
  bool store(const std::string& key, const CompiledArtifacts& artifacts) const;
  // Path of an entry (for tests that corrupt one on purpose): <dir>/<key[0:2]>/<key>.mbc.
  std::filesystem::path entryPath(const std::string& key) const;

 private:
  std::filesystem::path dir_;
};

}  // namespace mb
