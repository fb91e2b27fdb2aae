// buildEnvironment (environment.hpp): the name check, the process-wide cache, and the on-disk
// cache of built cubes. Building the studio or the sky at 128 takes seconds on lavapipe
// (docs/environments.md), so a second process reads the levels back instead: the entry is
// keyed by everything that determines them (the kernel's full GLSL, which holds the
// parameters and the bricks' sources, the sample count, the size, the toolchain and the
// device), carries a hash of its payload, and is written atomically; a corrupt entry is
// ignored and rebuilt.
#include "preview/environment.hpp"

#include <xxhash.h>

#include <cstring>
#include <map>
#include <mutex>

#include "compile/glsl_compiler.hpp"
#include "compile/shader_cache.hpp"
#include "core/atomic_file.hpp"
#include "core/diagnostics.hpp"
#include "core/input_file.hpp"
#include "harness/vulkan_harness.hpp"
#include "library/shader_library.hpp"
#include "preview/environment_cache.hpp"
#include "preview/environment_prefilter.hpp"
#include "preview/environment_sh.hpp"

namespace mb::preview {
namespace {

namespace fs = std::filesystem;

constexpr const char* kEntryMagic = "matbricks-environment-1\n";
constexpr uint32_t kMaxBaseSize = 2048;

void put(std::string& out, const void* data, size_t bytes) { out.append(static_cast<const char*>(data), bytes); }

std::string encodeLevels(const std::vector<CubeLevel>& levels) {
  std::string payload;
  const auto count = static_cast<uint32_t>(levels.size());
  put(payload, &count, sizeof count);
  for (const CubeLevel& l : levels) {
    put(payload, &l.size, sizeof l.size);
    put(payload, l.rgba.data(), l.rgba.size() * sizeof(float));
  }
  const uint64_t hash = XXH3_64bits(payload.data(), payload.size()), size = payload.size();
  std::string entry = kEntryMagic;
  put(entry, &size, sizeof size);
  put(entry, &hash, sizeof hash);
  return entry + payload;
}

// The size of a whole entry for a chain of levels from `baseSize` down to 1.
std::uintmax_t entryBytes(uint32_t baseSize) {
  std::uintmax_t bytes = std::strlen(kEntryMagic) + 16 + sizeof(uint32_t);
  for (uint32_t size = baseSize; size > 0; size /= 2)
    bytes += sizeof(uint32_t) + std::uintmax_t{6} * size * size * 4 * sizeof(float);
  return bytes;
}

// False for anything but a whole entry whose levels are the expected chain.
bool decodeLevels(const std::string& entry, uint32_t baseSize, std::vector<CubeLevel>& out) {
  const size_t head = std::strlen(kEntryMagic) + 16;
  if (entry.size() < head || entry.compare(0, std::strlen(kEntryMagic), kEntryMagic) != 0) return false;
  uint64_t size = 0, hash = 0;
  std::memcpy(&size, entry.data() + head - 16, 8);
  std::memcpy(&hash, entry.data() + head - 8, 8);
  if (entry.size() != head + size || XXH3_64bits(entry.data() + head, size) != hash) return false;
  size_t at = head;
  auto take = [&](void* dst, size_t bytes) {
    if (entry.size() - at < bytes) return false;
    std::memcpy(dst, entry.data() + at, bytes);
    at += bytes;
    return true;
  };
  uint32_t count = 0;
  if (!take(&count, sizeof count)) return false;
  std::vector<CubeLevel> levels(count);
  for (uint32_t i = 0; i < count; ++i) {
    CubeLevel& l = levels[i];
    if (!take(&l.size, sizeof l.size) || l.size != (baseSize >> i) || l.size == 0) return false;
    l.rgba.resize(size_t{6} * l.size * l.size * 4);
    if (!take(l.rgba.data(), l.rgba.size() * sizeof(float))) return false;
  }
  if (at != entry.size() || (count > 0 && levels.back().size != 1)) return false;
  out = std::move(levels);
  return true;
}

}  // namespace

fs::path environmentCacheEntry(const ShaderLibrary& lib, const std::string& name, harness::VulkanHarness& gpu,
                               uint32_t baseSize, const fs::path& cacheDir) {
  if (cacheDir.empty()) return {};
  const std::string glsl = prefilterKernelGlsl(lib, name, kPrefilterSamples);
  const std::string key = ShaderCache::key({kEntryMagic, glsl, std::to_string(baseSize),
                                            std::to_string(kPrefilterSamples), toolchainVersion(), gpu.deviceName()});
  return cacheDir / "environments" / (key + ".mbenv");
}

std::vector<CubeLevel> prefilteredLevels(const ShaderLibrary& lib, const std::string& name, harness::VulkanHarness& gpu,
                                         uint32_t baseSize, const fs::path& cacheDir, bool* fromCache) {
  const fs::path path = environmentCacheEntry(lib, name, gpu, baseSize, cacheDir);
  std::vector<CubeLevel> levels;
  if (fromCache) *fromCache = false;
  if (!path.empty()) {
    // Read through the one input reader, bounded by the entry's exact size: a damaged or
    // planted entry (a FIFO, a link to /dev/zero) is a miss, never a hang.
    InputFileError error;
    const InputKind kind{"environment cache entry", entryBytes(baseSize)};
    const std::optional<std::string> bytes = readInputFile(path, kind, error);
    if (bytes && decodeLevels(*bytes, baseSize, levels)) {
      if (fromCache) *fromCache = true;
      return levels;
    }
  }
  levels = prefilterOnGpu(gpu, prefilterKernelGlsl(lib, name, kPrefilterSamples), name, baseSize);
  if (!path.empty()) {
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    // An unwritable cache is not an error: the next process builds again.
    if (!ec) replaceFileAtomically(path, encodeLevels(levels));
  }
  return levels;
}

namespace {

void checkArguments(const std::string& name, uint32_t baseSize) {
  const std::vector<std::string> names = environmentNames();
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    throw DiagnosticError({{Severity::Error,
                            "E-UNKNOWN-ENVIRONMENT",
                            {"<command line>", 0, 0},
                            "unknown environment '" + name + "'; the environments are: " + list,
                            didYouMean(name, names)}});
  }
  if (baseSize == 0 || baseSize > kMaxBaseSize || (baseSize & (baseSize - 1)) != 0) {
    throw DiagnosticError({{Severity::Error,
                            "E-ENVIRONMENT-SIZE",
                            {"<command line>", 0, 0},
                            "environment size " + std::to_string(baseSize) + " is not a power of two in 1.." +
                                std::to_string(kMaxBaseSize),
                            ""}});
  }
}

}  // namespace

std::vector<std::string> environmentNames() { return {"studio", "sky"}; }

EnvironmentMaps buildEnvironment(const ShaderLibrary& lib, const std::string& name, harness::VulkanHarness& gpu,
                                 uint32_t baseSize) {
  checkArguments(name, baseSize);
  static std::mutex mutex;
  // Keyed by the kernel's source: another library (--shaderlib) may prefilter differently.
  static std::map<std::pair<std::string, uint32_t>, EnvironmentMaps> built;
  const std::pair<std::string, uint32_t> key{prefilterKernelGlsl(lib, name, kPrefilterSamples), baseSize};
  std::lock_guard lock(mutex);
  auto it = built.find(key);
  if (it != built.end()) return it->second;
  EnvironmentMaps env;
  env.name = name;
  env.samplesPerTexel = kPrefilterSamples;
  env.levels = prefilteredLevels(lib, name, gpu, baseSize, ShaderCache::defaultDir());
  projectSh9(env.levels.front(), env.sh);
  return built.emplace(key, std::move(env)).first->second;
}

}  // namespace mb::preview
