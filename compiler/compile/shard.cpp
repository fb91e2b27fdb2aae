// compile: shards and the shard set (shard.hpp).
#include "compile/shard.hpp"

#include <charconv>

#include "core/content_hash.hpp"
#include "core/diagnostics.hpp"
#include "core/input_file.hpp"
#include "core/json_document.hpp"

namespace mb {
namespace fs = std::filesystem;
namespace {

constexpr unsigned kMaxShards = 4096;

bool parseUnsigned(const std::string& s, unsigned& v) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size() && !s.empty();
}

[[noreturn]] void shardError(const std::string& code, const SourceLocation& where, const std::string& message,
                             const std::string& suggestion = "") {
  throw DiagnosticError({{Severity::Error, code, where, message, suggestion}});
}

fs::path entryFile(const fs::path& dir, const std::string& key) { return dir / "entries" / (key + ".mbc"); }

// A 32-digit lowercase hex cache key: anything else in shard.json could name a path outside
// the shard's entries/ directory.
bool isCacheKey(const std::string& s) {
  return s.size() == 32 && s.find_first_not_of("0123456789abcdef") == std::string::npos;
}

}  // namespace

bool parseShardSpec(const std::string& text, ShardSpec& out, std::string& error) {
  const size_t slash = text.find('/');
  ShardSpec s;
  if (slash == std::string::npos || !parseUnsigned(text.substr(0, slash), s.index) ||
      !parseUnsigned(text.substr(slash + 1), s.count)) {
    error = "--shard takes i/N, e.g. 2/3 (shard 2 of 3), not '" + text + "'";
    return false;
  }
  if (s.count == 0 || s.count > kMaxShards || s.index == 0 || s.index > s.count) {
    error = "--shard " + text + ": need 1 <= i <= N <= " + std::to_string(kMaxShards);
    return false;
  }
  out = s;
  return true;
}

std::string planDigest(unsigned count, const std::vector<std::string>& unitKeys) {
  std::string text = std::string(kShardFormat) + "\n" + std::to_string(count) + "\n";
  for (const auto& k : unitKeys) text += k + "\n";
  return contentHash(text.data(), text.size());
}

ShardSet ShardSet::open(const std::vector<fs::path>& dirs) {
  ShardSet set;
  std::string firstFile;
  std::map<unsigned, fs::path> byIndex;
  for (const auto& dir : dirs) {
    const fs::path file = dir / "shard.json";
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
      shardError("E-SHARD-NOT-SHARD", {dir.string(), 0, 0},
                 "not a shard directory: it has no shard.json (expected the -o of 'compile --shard i/N')");
    const JsonDocument doc = JsonDocument::load(file.string());
    const nlohmann::json& j = doc.root();
    auto field = [&](const char* name, nlohmann::json::value_t type) -> const nlohmann::json& {
      const std::string ptr = std::string("/") + name;
      if (!j.is_object() || !j.contains(name))
        shardError("E-SHARD-NOT-SHARD", doc.valueAt(""),
                   std::string("shard.json has no '") + name + "' (not written by 'compile --shard')");
      const nlohmann::json& v = j[name];
      const bool ok = v.type() == type || (type == nlohmann::json::value_t::number_unsigned && v.is_number_unsigned());
      if (!ok) shardError("E-SHARD-NOT-SHARD", doc.valueAt(ptr), std::string("'") + name + "' has the wrong type");
      return v;
    };
    const std::string format = field("format", nlohmann::json::value_t::string).get<std::string>();
    if (format != kShardFormat)
      shardError("E-SHARD-NOT-SHARD", doc.valueAt("/format"),
                 "shard format '" + format + "', expected '" + kShardFormat + "' (made by another matbricks version)");
    const unsigned index = field("shard", nlohmann::json::value_t::number_unsigned).get<unsigned>();
    const unsigned count = field("of", nlohmann::json::value_t::number_unsigned).get<unsigned>();
    const std::string digest = field("plan", nlohmann::json::value_t::string).get<std::string>();
    const nlohmann::json& command = field("command", nlohmann::json::value_t::object);
    const nlohmann::json& entries = field("entries", nlohmann::json::value_t::array);
    if (count == 0 || count > kMaxShards || index == 0 || index > count)
      shardError("E-SHARD-NOT-SHARD", doc.valueAt("/shard"),
                 "shard " + std::to_string(index) + " of " + std::to_string(count) + " is not a valid shard");
    if (firstFile.empty()) {
      firstFile = file.string();
      set.count_ = count;
      set.digest_ = digest;
      set.command_ = command;
    } else if (count != set.count_ || digest != set.digest_ || command != set.command_) {
      shardError(
          "E-SHARD-MISMATCH",
          doc.valueAt(count != set.count_     ? "/of"
                      : digest != set.digest_ ? "/plan"
                                              : "/command"),
          "this shard belongs to another build than " + firstFile + " (" +
              (count != set.count_     ? "a split into " + std::to_string(count) + ", not " + std::to_string(set.count_)
               : digest != set.digest_ ? "another plan: other inputs, options or tool versions"
                                       : "another command line") +
              ")",
          "merge the shards of one 'compile --shard i/N' run");
    }
    if (!byIndex.emplace(index, dir).second)
      shardError("E-SHARD-INCOMPLETE", doc.valueAt("/shard"),
                 "shard " + std::to_string(index) + "/" + std::to_string(count) + " is given twice (also " +
                     byIndex[index].string() + ")");
    for (size_t e = 0; e < entries.size(); ++e) {
      const std::string ptr = "/entries/" + std::to_string(e) + "/key";
      if (!entries[e].is_object() || !entries[e].contains("key") || !entries[e]["key"].is_string() ||
          !isCacheKey(entries[e]["key"].get<std::string>()))
        shardError("E-SHARD-NOT-SHARD", doc.valueAt(ptr), "an entry needs 'key', a 32-digit hex cache key");
      const std::string key = entries[e]["key"].get<std::string>();
      set.entries_.emplace(key, entryFile(dir, key));
    }
  }
  if (dirs.empty()) shardError("E-SHARD-INCOMPLETE", {"", 0, 0}, "merge needs the shard directories");
  std::string missing;
  for (unsigned i = 1; i <= set.count_; ++i)
    if (!byIndex.count(i)) missing += (missing.empty() ? "" : ", ") + std::to_string(i);
  if (!missing.empty())
    shardError("E-SHARD-INCOMPLETE", {firstFile, 0, 0},
               "shard(s) " + missing + " of " + std::to_string(set.count_) + " are missing",
               "give every shard directory of the split");
  for (const auto& [index, dir] : byIndex) set.dirs_.push_back(dir);
  return set;
}

void ShardSet::requirePlan(const std::string& digest) const {
  if (digest == digest_) return;
  shardError("E-SHARD-MISMATCH", {(dirs_.front() / "shard.json").string(), 0, 0},
             "the shards split another build (plan " + digest_ + ") than these inputs give (plan " + digest +
                 "): a material, brick, option or tool version changed since they were compiled",
             "compile the shards again from the same inputs");
}

ShardSet::Lookup ShardSet::load(const CacheIdentity& unit, size_t unitIndex, CompiledArtifacts& out, std::string& where,
                                std::string& why) const {
  const auto it = entries_.find(unit.key);
  if (it == entries_.end()) {
    where = dirs_[unitIndex % count_].string();
    return Lookup::Missing;
  }
  where = it->second.string();
  // compile --shard writes every entry as a file: a link in its place, to another entry or
  // anywhere else, was put there by someone else.
  std::error_code ec;
  if (fs::symlink_status(it->second, ec).type() == fs::file_type::symlink) {
    why = "is a symbolic link, not the entry compile --shard wrote";
    return Lookup::Corrupt;
  }
  InputFileError error;
  const std::optional<std::string> bytes = readInputFile(it->second, input_kind::kShardFile, error);
  if (!bytes) {
    why = error.message;
    return Lookup::Corrupt;
  }
  CacheIdentity found;
  const EntryCheck check = decodeCacheEntry(*bytes, unit, out, &found);
  if (check == EntryCheck::Ok) return Lookup::Hit;
  why = describeEntryCheck(check, found);
  return Lookup::Corrupt;
}

}  // namespace mb
