// write: a shard directory (compile/shard.hpp says what it holds and how a build is split),
// written through a PackageWriter like any other output of ours.
#pragma once
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "compile/shard.hpp"
#include "write/package_writer.hpp"

namespace mb {

// Writes a shard directory as a streaming build hands its permutations over: each unit's
// entry when its first permutation arrives, shard.json at the end. `writer` was constructed
// with kind "shard"; `command` is what `merge` needs to rebuild the plan (the compile
// command's inputs, driver/compile_request.hpp).
class ShardWriter {
 public:
  ShardWriter(PackageWriter& writer, const ShardSpec& spec, nlohmann::json command);
  // A permutation of this shard (BuiltPermutation::inShard) with its unit's identity.
  void add(const CacheIdentity& unit, const CompiledArtifacts& artifacts, const std::string& permutationKey);
  void finish(const std::string& digest, size_t units);

 private:
  PackageWriter& writer_;
  ShardSpec spec_;
  nlohmann::json command_;
  nlohmann::json entries_ = nlohmann::json::array();
  std::map<std::string, size_t> byKey_;
};

}  // namespace mb
