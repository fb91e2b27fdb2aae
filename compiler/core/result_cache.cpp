#include "core/result_cache.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <iterator>

#include "core/atomic_file.hpp"
#include "core/content_hash.hpp"
#include "core/input_file.hpp"

namespace mb {
namespace fs = std::filesystem;
namespace {

// A result entry holds a few kilobytes of JSON; anything far larger is not one.
constexpr InputKind kResultEntry{"result cache entry", std::uintmax_t{16} << 20};

std::string valueHash(const nlohmann::json& value) {
  const std::string text = value.dump();
  return contentHash(text.data(), text.size());
}

}  // namespace

ResultCache::ResultCache(fs::path dir) : dir_(executableIdentity().empty() ? fs::path() : std::move(dir)) {}

const std::string& ResultCache::executableIdentity() {
  static const std::string identity = [] {
    std::ifstream in("/proc/self/exe", std::ios::binary);
    if (!in) return std::string();
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return bytes.empty() ? std::string() : contentHash(bytes.data(), bytes.size());
  }();
  return identity;
}

std::string ResultCache::key(const std::vector<std::string>& keyParts) const {
  std::vector<std::string> parts{kFormatVersion, executableIdentity()};
  parts.insert(parts.end(), keyParts.begin(), keyParts.end());
  return contentKey(parts);
}

fs::path ResultCache::entryPath(const std::string& kind, const std::vector<std::string>& keyParts) const {
  const std::string k = key(keyParts);
  return dir_ / kind / k.substr(0, 2) / (k + ".json");
}

std::optional<nlohmann::json> ResultCache::load(const std::string& kind, const std::vector<std::string>& keyParts) {
  std::optional<nlohmann::json> value;
  bool rejected = false;
  if (enabled()) {
    InputFileError error;
    const std::optional<std::string> bytes = readInputFile(entryPath(kind, keyParts), kResultEntry, error);
    if (bytes) {
      const nlohmann::json entry = nlohmann::json::parse(*bytes, nullptr, false);
      const bool whole = entry.is_object() && entry.value("format", "") == kFormatVersion &&
                         entry.value("kind", "") == kind && entry.value("key", "") == key(keyParts) &&
                         entry.contains("value") && entry.value("check", "") == valueHash(entry["value"]);
      if (whole)
        value = entry["value"];
      else
        rejected = true;
    } else {
      rejected = error.code != "E-FILE-NOT-FOUND";  // a directory, a FIFO, a huge file: not an entry
    }
  }
  std::lock_guard lock(mutex_);
  Counts& c = counts_[kind];
  (value ? c.hits : c.misses) += 1;
  c.rejected += rejected;
  return value;
}

void ResultCache::store(const std::string& kind, const std::vector<std::string>& keyParts,
                        const nlohmann::json& value) {
  if (!enabled()) return;
  const fs::path path = entryPath(kind, keyParts);
  const nlohmann::json entry{{"format", kFormatVersion},
                             {"kind", kind},
                             {"key", key(keyParts)},
                             {"value", value},
                             {"check", valueHash(value)}};
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  if (!ec) replaceFileAtomically(path, entry.dump());
}

ResultCache::Counts ResultCache::counts(const std::string& kind) const {
  std::lock_guard lock(mutex_);
  auto it = counts_.find(kind);
  return it == counts_.end() ? Counts{} : it->second;
}

void ResultCache::reject(const std::string& kind) {
  std::lock_guard lock(mutex_);
  Counts& c = counts_[kind];
  if (c.hits) --c.hits;
  ++c.misses;
  ++c.rejected;
}

nlohmann::json jsonNumber(double v) {
  if (std::isfinite(v)) return v;
  return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
}

double numberFromJson(const nlohmann::json& j) {
  if (j.is_number()) return j.get<double>();
  const std::string s = j.get<std::string>();
  if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
  if (s == "inf") return std::numeric_limits<double>::infinity();
  if (s == "-inf") return -std::numeric_limits<double>::infinity();
  throw std::invalid_argument("not a number in a result cache entry: " + s);
}

}  // namespace mb
