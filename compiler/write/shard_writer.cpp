// write: a shard directory (shard_writer.hpp).
#include "write/shard_writer.hpp"

namespace mb {

ShardWriter::ShardWriter(PackageWriter& writer, const ShardSpec& spec, nlohmann::json command)
    : writer_(writer), spec_(spec), command_(std::move(command)) {}

void ShardWriter::add(const CacheIdentity& unit, const CompiledArtifacts& artifacts,
                      const std::string& permutationKey) {
  auto [it, fresh] = byKey_.emplace(unit.key, entries_.size());
  if (fresh) {
    // The first permutation of a unit always carries its code (build.hpp BuiltSink).
    entries_.push_back({{"key", unit.key}, {"permutations", nlohmann::json::array()}});
    writer_.addFile("entries/" + unit.key + ".mbc", encodeCacheEntry(unit, artifacts));
  }
  entries_[it->second]["permutations"].push_back(permutationKey);
}

void ShardWriter::finish(const std::string& digest, size_t units) {
  nlohmann::json j;
  j["format"] = kShardFormat;
  j["shard"] = spec_.index;
  j["of"] = spec_.count;
  j["plan"] = digest;
  j["units"] = units;
  j["command"] = command_;
  j["entries"] = entries_;
  writer_.addFile("shard.json", j.dump(2) + "\n");
}

}  // namespace mb
