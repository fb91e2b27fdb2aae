// The content hash every layer names files and cache entries by: the package's SPIR-V file
// names, the output marker's per-file hashes, the compile cache's keys and a shard plan's
// digest. In core because compile and write both need it and neither may ask the other.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace mb {

// 64-bit xxHash of bytes, as 16 hex digits.
std::string contentHash(const void* data, size_t size);
// 128-bit xxHash (XXH3) over `parts`, each length-prefixed so that ("ab", "c") and ("a", "bc")
// differ, as 32 hex digits: the key of a compile cache or result cache entry.
std::string contentKey(const std::vector<std::string>& parts);

}  // namespace mb
