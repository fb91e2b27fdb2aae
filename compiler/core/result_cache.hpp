// A cache of measured and computed results (costs of SPIR-V kernels on a device, error
// statistics, white-furnace albedos) as JSON, in a folder of the compile cache's directory,
// so that a second `report` reuses what an earlier run on the same device measured
// (docs/report.md "Result cache").
//
// An entry is named by contentKey over the format, the running executable's own content hash
// and the caller's key parts (device, SPIR-V or GLSL, options): a rebuilt matbricks (an edited
// C++ reference, a changed cost method) never reads the results of another build. Each entry
// carries its key, its kind and a hash of its value; an entry that does not parse, fails the
// hash, or names another key or kind (truncated, edited, copied from elsewhere) is rejected,
// counted and recomputed, never trusted. Entries are written through replaceFileAtomically,
// so concurrent reports see a whole entry or none.
#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mb {

class ResultCache {
 public:
  // Entries live in `dir` (the caller passes <compile cache>/results); an empty dir, or an
  // executable whose bytes cannot be read, disables the cache: every lookup misses and
  // nothing is stored.
  explicit ResultCache(std::filesystem::path dir);

  // Version of the entry format and of the key's recipe.
  static constexpr const char* kFormatVersion = "matbricks-results-1";

  bool enabled() const { return !dir_.empty(); }
  // The value stored under (kind, keyParts), or nothing (no entry, or one rejected as above).
  // Thread-safe.
  std::optional<nlohmann::json> load(const std::string& kind, const std::vector<std::string>& keyParts);
  // Failures to write (read-only directory, full disk) are not errors: the next run computes
  // again. Thread-safe.
  void store(const std::string& kind, const std::vector<std::string>& keyParts, const nlohmann::json& value);

  struct Counts {
    uint64_t hits = 0;
    uint64_t misses = 0;    // computed in this run (rejected ones included)
    uint64_t rejected = 0;  // entries found but not trusted (damaged or foreign)
  };
  Counts counts(const std::string& kind) const;
  // A value load() returned that the caller could not decode (a well-formed entry of the
  // wrong shape): counted as rejected and missed instead of hit.
  void reject(const std::string& kind);
  // Where (kind, keyParts) is stored: <dir>/<kind>/<key[0:2]>/<key>.json (tests damage one).
  std::filesystem::path entryPath(const std::string& kind, const std::vector<std::string>& keyParts) const;

  // contentHash of the running executable's bytes (/proc/self/exe), read once; empty when
  // unreadable.
  static const std::string& executableIdentity();

 private:
  std::string key(const std::vector<std::string>& keyParts) const;
  std::filesystem::path dir_;
  mutable std::mutex mutex_;
  std::map<std::string, Counts> counts_;
};

// Doubles as a value holds them: finite ones as JSON numbers (nlohmann writes the shortest
// text that reads back to the same double), NaN and infinities as "nan", "inf", "-inf"
// (JSON has no number for them). numberFromJson throws (a std::exception) on anything
// else.
nlohmann::json jsonNumber(double v);
double numberFromJson(const nlohmann::json& j);

}  // namespace mb
