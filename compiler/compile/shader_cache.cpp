// compile: the on-disk cache (shader_cache.hpp, docs/targets.md "Cache").
//
// Entry file: a 32-byte header, then the payload.
//   header   "MBCACHE1" (8 bytes), XXH3-64 of kFormatVersion (u64), payload size (u64),
//            XXH3-64 of the payload (u64)
//   payload  the identity (u64 key length, key, u64 source digest length, source digest),
//            then the kernel, then the fragment shader (docs/fragment-stage.md; no words and a
//            null reflection when it was not built), each as: u64 SPIR-V word count, the
//            words; u64 target count, then per target u64 name length, name, u64 text length,
//            text; u64 reflection length, reflection JSON text;
//            then u64 include count, then per include u64 language length, language,
//            u64 text length, text
// Integers are little-endian as the host writes them: the cache is per machine.
#include "compile/shader_cache.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <xxhash.h>

#include "core/atomic_file.hpp"
#include "core/content_hash.hpp"
#include "core/input_file.hpp"

namespace mb {
namespace fs = std::filesystem;
namespace {

constexpr char kMagic[8] = {'M', 'B', 'C', 'A', 'C', 'H', 'E', '1'};
constexpr size_t kHeaderSize = 32;

uint64_t formatTag() { return XXH3_64bits(ShaderCache::kFormatVersion, std::strlen(ShaderCache::kFormatVersion)); }

void putU64(std::string& out, uint64_t v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); }
void putBytes(std::string& out, const std::string& bytes) {
  putU64(out, bytes.size());
  out += bytes;
}

// Reads the payload back; every length is bounds-checked, so a bad entry is reported, never
// read past its end.
class Reader {
 public:
  Reader(const std::string& bytes, size_t pos) : bytes_(bytes), pos_(pos) {}
  bool u64(uint64_t& v) {
    if (bytes_.size() - pos_ < sizeof v) return false;
    std::memcpy(&v, bytes_.data() + pos_, sizeof v);
    pos_ += sizeof v;
    return true;
  }
  bool raw(void* dst, uint64_t size) {
    if (bytes_.size() - pos_ < size) return false;
    // An empty module (a kernel-only entry has no fragment words) has a null data(): memcpy
    // must not see it, even for 0 bytes (UBSan's nonnull check).
    if (size != 0) std::memcpy(dst, bytes_.data() + pos_, size);
    pos_ += size;
    return true;
  }
  bool str(std::string& s) {
    uint64_t n = 0;
    if (!u64(n) || bytes_.size() - pos_ < n) return false;
    s.assign(bytes_.data() + pos_, n);
    pos_ += n;
    return true;
  }
  bool atEnd() const { return pos_ == bytes_.size(); }

 private:
  const std::string& bytes_;
  size_t pos_;
};

// One module: u64 SPIR-V word count, the words; u64 target count, then per target the name
// and the text; the reflection JSON text.
void putModule(std::string& out, const std::vector<uint32_t>& spirv, const std::map<std::string, std::string>& targets,
               const nlohmann::json& reflection) {
  putU64(out, spirv.size());
  out.append(reinterpret_cast<const char*>(spirv.data()), spirv.size() * sizeof(uint32_t));
  putU64(out, targets.size());
  for (const auto& [name, text] : targets) {
    putBytes(out, name);
    putBytes(out, text);
  }
  putBytes(out, reflection.dump());
}

bool readModule(Reader& r, uint64_t size, std::vector<uint32_t>& spirv, std::map<std::string, std::string>& targets,
                nlohmann::json& reflection) {
  uint64_t words = 0, count = 0;
  if (!r.u64(words) || words > size / sizeof(uint32_t)) return false;
  spirv.resize(words);
  if (!r.raw(spirv.data(), words * sizeof(uint32_t)) || !r.u64(count)) return false;
  for (uint64_t i = 0; i < count; ++i) {
    std::string name, text;
    if (!r.str(name) || !r.str(text)) return false;
    targets[name] = std::move(text);
  }
  std::string json;
  if (!r.str(json)) return false;
  reflection = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
  return !reflection.is_discarded();
}

}  // namespace

std::string encodeCacheEntry(const CacheIdentity& identity, const CompiledArtifacts& a) {
  std::string payload;
  putBytes(payload, identity.key);
  putBytes(payload, identity.source);
  putModule(payload, a.spirv, a.targets, a.reflection);
  putModule(payload, a.fragment.spirv, a.fragment.targets, a.fragment.reflection);
  putU64(payload, a.includes.size());
  for (const auto& [language, text] : a.includes) {
    putBytes(payload, language);
    putBytes(payload, text);
  }
  std::string file(kMagic, sizeof kMagic);
  putU64(file, formatTag());
  putU64(file, payload.size());
  putU64(file, XXH3_64bits(payload.data(), payload.size()));
  return file + payload;
}

EntryCheck decodeCacheEntry(const std::string& file, const CacheIdentity& expected, CompiledArtifacts& out,
                            CacheIdentity* found) {
  if (file.size() < kHeaderSize || std::memcmp(file.data(), kMagic, sizeof kMagic) != 0) return EntryCheck::Damaged;
  Reader header(file, sizeof kMagic);
  uint64_t tag = 0, size = 0, hash = 0;
  header.u64(tag);
  header.u64(size);
  header.u64(hash);
  if (tag != formatTag() || size != file.size() - kHeaderSize) return EntryCheck::Damaged;
  if (XXH3_64bits(file.data() + kHeaderSize, size) != hash) return EntryCheck::Damaged;
  Reader r(file, kHeaderSize);
  CacheIdentity identity;
  CompiledArtifacts a;
  uint64_t includes = 0;
  if (!r.str(identity.key) || !r.str(identity.source) || !readModule(r, size, a.spirv, a.targets, a.reflection) ||
      !readModule(r, size, a.fragment.spirv, a.fragment.targets, a.fragment.reflection) || !r.u64(includes))
    return EntryCheck::Damaged;
  for (uint64_t i = 0; i < includes; ++i) {
    std::string language, text;
    if (!r.str(language) || !r.str(text)) return EntryCheck::Damaged;
    a.includes[language] = std::move(text);
  }
  if (!r.atEnd()) return EntryCheck::Damaged;
  if (found) *found = identity;
  if (!(identity == expected)) return EntryCheck::OtherUnit;
  out = std::move(a);
  return EntryCheck::Ok;
}

std::string describeEntryCheck(EntryCheck check, const CacheIdentity& found) {
  switch (check) {
    case EntryCheck::Ok:
      return "is this unit's entry";
    case EntryCheck::Damaged:
      return "is truncated, damaged or of another format";
    case EntryCheck::OtherUnit:
      return found.key.size() == 32 ? "holds the entry of another unit (key " + found.key + ")"
                                    : "holds the entry of another unit";
  }
  return "";
}

ShaderCache::ShaderCache(fs::path dir) : dir_(std::move(dir)) {}

fs::path ShaderCache::defaultDir() {
  if (const char* d = std::getenv("MATBRICKS_CACHE_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return fs::path(x) / "matbricks";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".cache" / "matbricks";
  return {};  // nowhere to put it: uncached
}

std::string ShaderCache::key(const std::vector<std::string>& parts) { return contentKey(parts); }

CacheIdentity ShaderCache::identity(const std::string& key, const std::vector<std::string>& sources) {
  return {key, ShaderCache::key(sources)};
}

fs::path ShaderCache::entryPath(const std::string& key) const { return dir_ / key.substr(0, 2) / (key + ".mbc"); }

ShaderCache::Lookup ShaderCache::load(const CacheIdentity& identity, CompiledArtifacts& out, std::string* why) const {
  if (!enabled()) return Lookup::Miss;
  const fs::path path = entryPath(identity.key);
  std::error_code ec;
  // No entry at all (not even a dangling link): a plain miss.
  if (fs::symlink_status(path, ec).type() == fs::file_type::not_found) return Lookup::Miss;
  InputFileError error;
  const std::optional<std::string> bytes = readInputFile(path, input_kind::kCacheEntry, error);
  Lookup result = Lookup::Hit;
  if (!bytes) {
    if (why) *why = error.message;
    result = Lookup::Unreadable;
  } else {
    CacheIdentity found;
    const EntryCheck check = decodeCacheEntry(*bytes, identity, out, &found);
    if (check == EntryCheck::Ok) return Lookup::Hit;
    if (why) *why = path.string() + " " + describeEntryCheck(check, found);
    result = check == EntryCheck::OtherUnit ? Lookup::OtherUnit : Lookup::Corrupt;
  }
  // Evict it so the rebuilt entry replaces it (a symlink goes, never what it points to). A
  // concurrent writer renames a whole entry over the path; at worst this removes that fresh
  // entry and a later run rebuilds it.
  fs::remove(path, ec);
  return result;
}

void ShaderCache::evict(const std::string& key) const {
  if (!enabled()) return;
  std::error_code ec;
  fs::remove(entryPath(key), ec);
}

bool ShaderCache::store(const CacheIdentity& identity, const CompiledArtifacts& artifacts) const {
  if (!enabled()) return false;
  const fs::path path = entryPath(identity.key);
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  if (ec) return false;
  // Two writers of one key write identical bytes; a reader never sees a partial entry.
  return replaceFileAtomically(path, encodeCacheEntry(identity, artifacts));
}

}  // namespace mb
