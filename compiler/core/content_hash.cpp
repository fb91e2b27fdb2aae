#include "core/content_hash.hpp"

#include <xxhash.h>

#include <cstdio>

namespace mb {

std::string contentHash(const void* data, size_t size) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(XXH64(data, size, 0)));
  return buf;
}

}  // namespace mb
