// How a run of N records is cut into dispatches ("chunks") and buffers ("segments").
// Pure arithmetic, kept apart from the Vulkan code so that tests can check the rules with
// limits that no real device has (large alignments, tiny allocation caps).
#pragma once
#include <cstdint>
#include <vector>

namespace mb::harness {

inline constexpr uint32_t kLocalSizeX = 64;  // the kernel contract's local_size_x

struct ChunkLimits {
  uint64_t maxGroupsX = 0;       // maxComputeWorkGroupCount[0]
  uint64_t maxRangeBytes = 0;    // maxStorageBufferRange
  uint64_t offsetAlignment = 1;  // minStorageBufferOffsetAlignment
  uint64_t maxSegmentBytes = 0;  // largest single buffer the harness allocates
  uint64_t recordCap = 0;        // DeviceOptions::maxRecordsPerChunk (0 = none)
};

// One dispatch. Offsets and ranges are bytes within its segment's buffers; ranges are
// never 0 (a stride-0 side binds 4 dummy bytes) because a descriptor range must not be.
struct Chunk {
  uint64_t firstRecord = 0;
  uint32_t records = 0;
  uint32_t segment = 0;
  uint64_t inOffset = 0, inRange = 0;
  uint64_t outOffset = 0, outRange = 0;
};

// One input buffer and one output buffer holding a run of whole chunks.
struct Segment {
  uint64_t firstRecord = 0;
  uint64_t records = 0;
  uint64_t inBytes = 0;  // buffer sizes, at least 4
  uint64_t outBytes = 0;
};

struct ChunkPlan {
  uint64_t recordsPerChunk = 0;
  std::vector<Segment> segments;
  std::vector<Chunk> chunks;
};

// Throws HarnessError when one record does not fit the limits. count 0 gives an empty plan.
// Strides are in floats.
ChunkPlan planChunks(uint64_t count, uint32_t inStride, uint32_t outStride, const ChunkLimits& limits);

}  // namespace mb::harness
