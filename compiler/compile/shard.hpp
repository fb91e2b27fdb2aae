// compile: deterministic shards of one build, and the set of shard directories `merge` reads
// (docs/targets.md "Shards"). Writing a shard directory is write/'s (write/shard_writer.hpp).
//
// A build's compile units (distinct emitted GLSL, in plan order) are dealt round-robin:
// shard i of N owns the units whose index is i-1 modulo N, so N machines compile disjoint,
// equal shares and together exactly the whole. A shard directory holds:
//   .matbricks-package   the output marker, kind "shard"
//   shard.json           format, shard i of N, the plan digest, the command's inputs, and per
//                        entry its cache key and the permutation keys that use it
//   entries/<key>.mbc    one compile cache entry (encodeCacheEntry) per owned unit; it
//                        carries its unit's CacheIdentity, which merge checks against
//                        the unit the rebuilt plan asks for
// The plan digest hashes N and every unit's cache key in order. Cache keys cover the emitted
// GLSL, brick sources, options, targets and tool versions, so shards agree on it exactly when
// they split the same build; `merge` refuses any other set.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compile/shader_cache.hpp"

namespace mb {

struct ShardSpec {
  unsigned index = 0;  // 1-based
  unsigned count = 0;  // 0: the whole build
  bool whole() const { return count == 0; }
  bool owns(size_t unit) const { return whole() || unit % count == index - 1; }
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// "i/N" with 1 <= i <= N <= 4096. Returns false with `error` set otherwise.
bool parseShardSpec(const std::string& text, ShardSpec& out, std::string& error);

inline constexpr const char* kShardFormat = "matbricks-shard-1";

// Digest of a build's split (see above): 16 hex digits.
std::string planDigest(unsigned count, const std::vector<std::string>& unitKeys);

// Shard directories given to `merge`: checked to be shards 1..N of one split, each once.
class ShardSet {
 public:
  // Throws DiagnosticError: E-SHARD-NOT-SHARD (no shard.json, or not ours), E-JSON-SYNTAX,
  // E-SHARD-MISMATCH (different N, plan or command), E-SHARD-INCOMPLETE (a shard missing
  // or given twice).
  static ShardSet open(const std::vector<std::filesystem::path>& dirs);

  unsigned count() const { return count_; }
  const std::string& digest() const { return digest_; }
  const nlohmann::json& command() const { return command_; }
  // Throws E-SHARD-MISMATCH naming the shards when the rebuilt plan's digest differs.
  void requirePlan(const std::string& digest) const;

  enum class Lookup { Hit, Missing, Corrupt };
  // Thread-safe. `where` is set to the entry's file (Corrupt) or the shard that should have
  // held it (Missing, given the unit's index); on Corrupt `why` says what is wrong with it:
  // not a regular file (a symlink, even to another entry, a FIFO, a device), too large,
  // unreadable, damaged, or an intact entry of another unit (entries swapped or copied).
  Lookup load(const CacheIdentity& unit, size_t unitIndex, CompiledArtifacts& out, std::string& where,
              std::string& why) const;

 private:
  unsigned count_ = 0;
  std::string digest_;
  nlohmann::json command_;
  std::vector<std::filesystem::path> dirs_;               // by shard index - 1
  std::map<std::string, std::filesystem::path> entries_;  // cache key -> entry file
};

}  // namespace mb
