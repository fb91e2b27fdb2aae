// The content hash every layer names files and cache entries by: the package's SPIR-V file
// names, the output marker's per-file hashes, the compile cache's keys and a shard plan's
// digest. In core because compile and write both need it and neither may ask the other.
#pragma once
#include <cstddef>
#include <string>

namespace mb {

// 64-bit xxHash of bytes, as 16 hex digits.
std::string contentHash(const void* data, size_t size);

}  // namespace mb
