#include "harness/chunk_plan.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <string>

#include "harness/vulkan_harness.hpp"

namespace mb::harness {
namespace {

constexpr uint64_t kFloatBytes = 4;
// A stride-0 side still needs a bound, non-empty buffer.
constexpr uint64_t kMinBinding = 4;

// Smallest record count whose byte size (records * stride floats) is a multiple of the
// offset alignment, so that chunks of a multiple of it start on aligned offsets.
uint64_t alignmentGranule(uint32_t stride, uint64_t alignment) {
  if (stride == 0 || alignment <= 1) return 1;
  const uint64_t recordBytes = kFloatBytes * stride;
  return alignment / std::gcd(alignment, recordBytes);
}

// The most records one chunk may hold under the device limits alone.
uint64_t deviceRecordCap(uint32_t inStride, uint32_t outStride, const ChunkLimits& limits) {
  // The push constant `count` is a uint.
  uint64_t cap = std::min<uint64_t>(limits.maxGroupsX * kLocalSizeX, std::numeric_limits<uint32_t>::max());
  const uint64_t maxBytes = std::min(limits.maxRangeBytes, limits.maxSegmentBytes);
  for (uint32_t stride : {inStride, outStride}) {
    if (stride != 0) cap = std::min(cap, maxBytes / (kFloatBytes * stride));
  }
  return cap;
}

uint64_t recordsPerChunk(uint64_t count, uint32_t inStride, uint32_t outStride, const ChunkLimits& limits) {
  const uint64_t deviceCap = deviceRecordCap(inStride, outStride, limits);
  if (deviceCap == 0) {
    throw HarnessError("one record (" + std::to_string(inStride) + " in, " + std::to_string(outStride) +
                       " out floats) exceeds the device's " + "dispatch or storage-buffer limits");
  }
  const uint64_t cap = limits.recordCap ? std::min(deviceCap, limits.recordCap) : deviceCap;
  if (count <= cap) return count;  // one chunk at offset 0: alignment is moot

  const uint64_t granule =
      std::lcm(alignmentGranule(inStride, limits.offsetAlignment), alignmentGranule(outStride, limits.offsetAlignment));
  const uint64_t per = cap / granule * granule;
  if (per != 0) return per;
  // Only the test hook can ask for less than one granule; the device can still take it.
  if (granule <= deviceCap) return granule;
  throw HarnessError("cannot split the run into aligned chunks: minStorageBufferOffsetAlignment " +
                     std::to_string(limits.offsetAlignment) + " needs " + std::to_string(granule) +
                     " records per chunk, the device allows " + std::to_string(deviceCap));
}

uint64_t sideBytes(uint64_t records, uint32_t stride) { return records * kFloatBytes * stride; }

}  // namespace

ChunkPlan planChunks(uint64_t count, uint32_t inStride, uint32_t outStride, const ChunkLimits& limits) {
  ChunkPlan plan;
  if (count == 0) return plan;
  plan.recordsPerChunk = recordsPerChunk(count, inStride, outStride, limits);

  // Whole chunks per segment, so no chunk straddles two buffers.
  const uint64_t chunkBytes = sideBytes(plan.recordsPerChunk, std::max(inStride, outStride));
  const uint64_t chunksPerSegment = chunkBytes == 0 ? std::numeric_limits<uint64_t>::max()
                                                    : std::max<uint64_t>(1, limits.maxSegmentBytes / chunkBytes);
  const uint64_t recordsPerSegment =
      plan.recordsPerChunk * std::min(chunksPerSegment, (count + plan.recordsPerChunk - 1) / plan.recordsPerChunk);

  for (uint64_t first = 0; first < count; first += recordsPerSegment) {
    Segment seg;
    seg.firstRecord = first;
    seg.records = std::min(recordsPerSegment, count - first);
    seg.inBytes = std::max(kMinBinding, sideBytes(seg.records, inStride));
    seg.outBytes = std::max(kMinBinding, sideBytes(seg.records, outStride));
    const auto segIndex = static_cast<uint32_t>(plan.segments.size());
    plan.segments.push_back(seg);

    for (uint64_t local = 0; local < seg.records; local += plan.recordsPerChunk) {
      Chunk c;
      c.firstRecord = first + local;
      c.records = static_cast<uint32_t>(std::min(plan.recordsPerChunk, seg.records - local));
      c.segment = segIndex;
      c.inOffset = sideBytes(local, inStride);
      c.inRange = std::max(kMinBinding, sideBytes(c.records, inStride));
      c.outOffset = sideBytes(local, outStride);
      c.outRange = std::max(kMinBinding, sideBytes(c.records, outStride));
      plan.chunks.push_back(c);
    }
  }
  return plan;
}

}  // namespace mb::harness
