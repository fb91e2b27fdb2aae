// The on-disk cache of built environment cubes behind buildEnvironment (environment.cpp),
// exposed so that tests can drive it with a directory of their own.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "library/shader_library.hpp"
#include "preview/environment.hpp"

namespace mb::preview {

// The levels of environment `name` at `baseSize`, prefiltered by the kernel built from `lib`'s
// bricks (environment_prefilter.hpp): read from <cacheDir>/environments/<key>.mbenv when a
// whole, intact entry is there (the key holds the kernel's source), else prefiltered on `gpu`
// and stored there atomically (an empty cacheDir: always built, never stored). *fromCache says
// which. The name and size must have been checked (buildEnvironment does).
std::vector<CubeLevel> prefilteredLevels(const ShaderLibrary& lib, const std::string& name, harness::VulkanHarness& gpu,
                                         uint32_t baseSize, const std::filesystem::path& cacheDir,
                                         bool* fromCache = nullptr);

// The entry's path for these arguments (tests corrupt it on purpose).
std::filesystem::path environmentCacheEntry(const ShaderLibrary& lib, const std::string& name,
                                            harness::VulkanHarness& gpu, uint32_t baseSize,
                                            const std::filesystem::path& cacheDir);

}  // namespace mb::preview
