// The Vulkan compute harness: exact results on lavapipe, chunking, device choice, the
// no-device path, and the validation-message capture that every GPU test relies on.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "compile/glsl_compiler.hpp"
#include "harness/chunk_plan.hpp"
#include "harness/vulkan_harness.hpp"
#include "support/harness_support.hpp"

using namespace mb::harness;

namespace {

// Follows the kernel contract. Input record: (a, b, global index as float). Output record:
// (a * b + global index, chunk-local index i). The test inputs make a * b and the sum exact
// in fp32, so the results are bit-exact whether or not the driver fuses into an fma.
const std::string kMulAddKernel = contractKernel(
    "  mbOut[i * 2u] = mbIn[i * 3u] * mbIn[i * 3u + 1u] + mbIn[i * 3u + 2u];\n"
    "  mbOut[i * 2u + 1u] = float(i);\n");
constexpr uint32_t kInStride = 3;
constexpr uint32_t kOutStride = 2;

std::vector<uint32_t> compileKernel(const std::string& source) {
  return mb::compileComputeGlsl(source, "test_harness.comp").spirv;
}

// a has at most 12 significant bits, b at most 9, so a * b is exact; |a * b + i| < 2^18
// with a granularity of 0.25, so the sum is exact too.
std::vector<float> makeInputs(uint64_t count) {
  std::vector<float> in(count * kInStride);
  for (uint64_t i = 0; i < count; ++i) {
    in[i * 3] = static_cast<float>(i % 1000) * 0.25f;
    in[i * 3 + 1] = static_cast<float>(static_cast<int>((i * 7) % 513) - 256);
    in[i * 3 + 2] = static_cast<float>(i);
  }
  return in;
}

float expectedFirst(const std::vector<float>& in, uint64_t i) { return in[i * 3] * in[i * 3 + 1] + in[i * 3 + 2]; }

// Counts records whose first output differs from the CPU (exact comparison).
uint64_t countMismatches(const std::vector<float>& in, const std::vector<float>& out, uint64_t count) {
  uint64_t bad = 0;
  for (uint64_t i = 0; i < count; ++i)
    if (out[i * kOutStride] != expectedFirst(in, i)) ++bad;
  return bad;
}

void requireNoValidationMessages(const VulkanHarness& h) {
  const std::vector<std::string> messages = h.validationMessages();
  for (const std::string& m : messages) UNSCOPED_INFO(m);
  REQUIRE(messages.empty());
}

// Sets (or, with nullptr, unsets) an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) saved_ = old;
    if (value)
      setenv(name, value, 1);
    else
      unsetenv(name);
  }
  ~ScopedEnv() {
    if (saved_)
      setenv(name_.c_str(), saved_->c_str(), 1);
    else
      unsetenv(name_.c_str());
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  std::string name_;
  std::optional<std::string> saved_;
};

}  // namespace

TEST_CASE("harness runs a kernel over 100000 records exactly", "[harness][vulkan]") {
  VulkanHarness h(testDeviceOptions());
  auto kernel = h.createKernel(compileKernel(kMulAddKernel));
  const uint64_t count = 100000;
  const std::vector<float> in = makeInputs(count);

  const RunResult r = h.run(*kernel, in, kInStride, kOutStride, count);

  REQUIRE(r.outputs.size() == count * kOutStride);
  CHECK(r.chunks == 1);
  CHECK(r.gpuMs >= 0.0);
  CHECK(countMismatches(in, r.outputs, count) == 0);
  uint64_t badIndex = 0;  // one chunk: the local index is the global one
  for (uint64_t i = 0; i < count; ++i)
    if (r.outputs[i * kOutStride + 1] != static_cast<float>(i)) ++badIndex;
  CHECK(badIndex == 0);
  requireNoValidationMessages(h);
}

TEST_CASE("harness splits a run into chunks with identical results", "[harness][vulkan]") {
  DeviceOptions options = testDeviceOptions();
  options.maxRecordsPerChunk = 1000;
  VulkanHarness h(options);
  auto kernel = h.createKernel(compileKernel(kMulAddKernel));
  const uint64_t count = 12345;  // not a multiple of the chunk size
  const std::vector<float> in = makeInputs(count);

  const RunResult r = h.run(*kernel, in, kInStride, kOutStride, count);

  REQUIRE(r.outputs.size() == count * kOutStride);
  CHECK(r.chunks >= 13);
  CHECK(countMismatches(in, r.outputs, count) == 0);
  // The local index restarts at 0 exactly once per chunk and otherwise counts up by one:
  // the chunks cover the records in order, each with the right push-constant count.
  uint64_t restarts = 0, breaks = 0;
  for (uint64_t i = 0; i < count; ++i) {
    const float local = r.outputs[i * kOutStride + 1];
    if (local == 0.0f)
      ++restarts;
    else if (i == 0 || local != r.outputs[(i - 1) * kOutStride + 1] + 1.0f)
      ++breaks;
  }
  CHECK(restarts == r.chunks);
  CHECK(breaks == 0);
  requireNoValidationMessages(h);

  SECTION("the same kernel unchunked gives the same first outputs") {
    VulkanHarness whole(testDeviceOptions());
    auto wholeKernel = whole.createKernel(compileKernel(kMulAddKernel));
    const RunResult w = whole.run(*wholeKernel, in, kInStride, kOutStride, count);
    REQUIRE(w.chunks == 1);
    uint64_t differ = 0;
    for (uint64_t i = 0; i < count; ++i)
      if (w.outputs[i * kOutStride] != r.outputs[i * kOutStride]) ++differ;
    CHECK(differ == 0);
    requireNoValidationMessages(whole);
  }
}

TEST_CASE("harness handles empty runs and rejects bad arguments", "[harness][vulkan]") {
  VulkanHarness h(testDeviceOptions());
  auto kernel = h.createKernel(compileKernel(kMulAddKernel));

  const RunResult empty = h.run(*kernel, {}, kInStride, kOutStride, 0);
  CHECK(empty.outputs.empty());
  CHECK(empty.chunks == 0);

  CHECK_THROWS_AS(h.run(*kernel, std::vector<float>(5), kInStride, kOutStride, 2), HarnessError);
  CHECK_THROWS_AS(h.createKernel({}), HarnessError);
  CHECK_THROWS_AS(h.createKernel({1, 2, 3, 4, 5}), HarnessError);
  requireNoValidationMessages(h);
}

// A table the kernel reads beside its records (a validation probe's LTC table): record i looks
// up entry mbIn[i] of it. Bound whole to every chunk, so a capped chunk size changes nothing.
const std::string kTableKernel =
    contractKernel("  mbOut[i] = mbTable[uint(mbIn[i])];\n",
                   "layout(std430, set = 0, binding = 2) readonly buffer MbTable { float mbTable[]; };\n");

TEST_CASE("a kernel reads its table buffer, whole in every chunk", "[harness][vulkan]") {
  DeviceOptions options = testDeviceOptions();
  options.maxRecordsPerChunk = 1000;  // several chunks
  VulkanHarness h(options);
  const auto spirv = compileKernel(kTableKernel);
  auto kernel = h.createKernel(spirv, 0, true);
  std::vector<float> table(777);
  for (size_t k = 0; k < table.size(); ++k) table[k] = 0.5f + static_cast<float>(k * k % 1013);
  const uint64_t count = 5000;
  std::vector<float> in(count);
  for (uint64_t i = 0; i < count; ++i) in[i] = static_cast<float>((i * 31) % table.size());
  const RunResult r = h.run(*kernel, in, 1, 1, count, {}, &table);
  CHECK(r.chunks >= 5);
  uint64_t bad = 0;
  for (uint64_t i = 0; i < count; ++i) bad += r.outputs[i] != table[static_cast<size_t>(in[i])];
  CHECK(bad == 0);
  // kernelFor keeps a module's kernel with the table's layout apart from its kernel without
  // (a layout may declare a binding the module does not use).
  CHECK(h.kernelFor(spirv, true) == h.kernelFor(spirv, true));
  const auto mulAdd = compileKernel(kMulAddKernel);
  CHECK(h.kernelFor(mulAdd, true) != h.kernelFor(mulAdd, false));

  CHECK_THROWS_WITH(h.run(*kernel, in, 1, 1, count), "run: the kernel reads a table, none given");
  auto plain = h.createKernel(compileKernel(kMulAddKernel));
  CHECK_THROWS_WITH(h.run(*plain, makeInputs(4), kInStride, kOutStride, 4, {}, &table),
                    "run: a table given to a kernel that reads none");
  CHECK_THROWS_WITH(h.createKernel(spirv, 1, true), "createKernel: a kernel samples textures or reads a table");
  requireNoValidationMessages(h);
}

TEST_CASE("harness reports device limits and picks lavapipe", "[harness][vulkan]") {
  VulkanHarness h(testDeviceOptions());
  CHECK(h.maxWorkGroupCountX() > 0);
  CHECK(h.maxStorageBufferRange() > 0);
  // CTest points VK_ICD_FILENAMES at lavapipe (tests/CMakeLists.txt).
  INFO("device: " << h.deviceName());
  CHECK(h.deviceName().find("llvmpipe") != std::string::npos);
  CHECK(h.isLavapipe());

  SECTION("a case-insensitive substring selects the device") {
    DeviceOptions options = testDeviceOptions();
    options.device = "LLVMPIPE";
    VulkanHarness named(options);
    CHECK(named.deviceName() == h.deviceName());
  }
}

TEST_CASE("harness rejects an unknown device name", "[harness][vulkan]") {
  DeviceOptions options = testDeviceOptions();
  options.device = "no-such-gpu-xyzzy";
  try {
    VulkanHarness h(options);
    FAIL("expected HarnessError");
  } catch (const HarnessError& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("no-such-gpu-xyzzy") != std::string::npos);
    CHECK(what.find("llvmpipe") != std::string::npos);  // lists what there is
    CHECK(what.find('\n') == std::string::npos);
  }
}

TEST_CASE("harness without a Vulkan driver throws one clear line", "[harness]") {
  const ScopedEnv icd("VK_ICD_FILENAMES", "/nonexistent/none.json");
  const ScopedEnv driverFiles("VK_DRIVER_FILES", nullptr);  // would take precedence
  const ScopedEnv addDriverFiles("VK_ADD_DRIVER_FILES", nullptr);
  try {
    VulkanHarness h(testDeviceOptions());
    FAIL("expected HarnessError");
  } catch (const HarnessError& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.rfind("no Vulkan device", 0) == 0);
    CHECK(what.find("VK_ICD_FILENAMES") != std::string::npos);
    CHECK(what.find('\n') == std::string::npos);
  }
}

TEST_CASE("harness captures validation-layer errors", "[harness][vulkan]") {
  DeviceOptions options = testDeviceOptions();
  if (!options.validation) {
    WARN("MATBRICKS_VALIDATION is not set: skipping");
    return;
  }
  // The shader reads a push constant past the 4 bytes the contract's layout declares.
  const char* outOfRange = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer MbIn { float mbIn[]; };
layout(std430, set = 0, binding = 1) writeonly buffer MbOut { float mbOut[]; };
layout(push_constant) uniform MbPush { uint count; uint extra; } mbPush;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= mbPush.count) return;
  mbOut[i] = mbIn[i] + float(mbPush.extra);
}
)";
  VulkanHarness h(options);
  auto kernel = h.createKernel(compileKernel(outOfRange));
  const std::vector<std::string> messages = h.validationMessages();
  REQUIRE_FALSE(messages.empty());
  CHECK(messages.front().rfind("error: ", 0) == 0);
  h.clearValidationMessages();
  CHECK(h.validationMessages().empty());
}

TEST_CASE("a kernel may outlive its harness", "[harness][vulkan]") {
  auto h = std::make_unique<VulkanHarness>(testDeviceOptions());
  std::shared_ptr<Kernel> kernel = h->createKernel(compileKernel(kMulAddKernel));
  const std::vector<float> in = makeInputs(10);
  CHECK(h->run(*kernel, in, kInStride, kOutStride, 10).outputs.size() == 10 * kOutStride);
  requireNoValidationMessages(*h);
  h.reset();       // the kernel keeps the device alive ...
  kernel.reset();  // ... and releases it here, pipeline first
  SUCCEED();
}

TEST_CASE("concurrent runs on one harness are safe", "[harness][vulkan]") {
  VulkanHarness h(testDeviceOptions());
  auto kernel = h.createKernel(compileKernel(kMulAddKernel));
  const uint64_t count = 20000;
  const std::vector<float> in = makeInputs(count);
  // Catch assertions are not thread-safe: threads only record, the main thread checks.
  std::vector<uint64_t> mismatches(4, 0);
  std::vector<std::string> errors(4);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < mismatches.size(); ++t) {
    threads.emplace_back([&, t] {
      try {
        const RunResult r = h.run(*kernel, in, kInStride, kOutStride, count);
        mismatches[t] = countMismatches(in, r.outputs, count);
      } catch (const std::exception& e) {
        errors[t] = e.what();
      }
    });
  }
  for (std::thread& th : threads) th.join();
  for (size_t t = 0; t < mismatches.size(); ++t) {
    INFO("thread " << t);
    CHECK(errors[t].empty());
    CHECK(mismatches[t] == 0);
  }
  requireNoValidationMessages(h);
}

TEST_CASE("a kernel from another harness is rejected", "[harness][vulkan]") {
  VulkanHarness a(testDeviceOptions());
  VulkanHarness b(testDeviceOptions());
  auto kernel = a.createKernel(compileKernel(kMulAddKernel));
  CHECK_THROWS_AS(b.run(*kernel, makeInputs(1), kInStride, kOutStride, 1), HarnessError);
}

// The chunk planner is pure arithmetic: check its rules with limits no real device has.
TEST_CASE("chunk plan respects dispatch and range and alignment and allocation limits", "[harness]") {
  ChunkLimits limits;
  limits.maxGroupsX = 100;         // 6400 records per dispatch
  limits.maxRangeBytes = 1 << 16;  // 64 KiB per binding
  limits.offsetAlignment = 256;
  limits.maxSegmentBytes = 1 << 18;            // 256 KiB per buffer
  const uint32_t inStride = 3, outStride = 5;  // 12 and 20 bytes per record
  const uint64_t count = 100001;

  const ChunkPlan plan = planChunks(count, inStride, outStride, limits);

  REQUIRE_FALSE(plan.chunks.empty());
  REQUIRE(plan.segments.size() > 1);
  uint64_t next = 0;
  for (const Chunk& c : plan.chunks) {
    INFO("chunk at record " << c.firstRecord);
    CHECK(c.firstRecord == next);  // in order, no gaps, no overlap
    next += c.records;
    CHECK(c.records <= limits.maxGroupsX * kLocalSizeX);
    CHECK(c.inRange <= limits.maxRangeBytes);
    CHECK(c.outRange <= limits.maxRangeBytes);
    CHECK(c.inOffset % limits.offsetAlignment == 0);
    CHECK(c.outOffset % limits.offsetAlignment == 0);
    const Segment& seg = plan.segments.at(c.segment);
    CHECK(c.firstRecord >= seg.firstRecord);
    CHECK(c.inOffset + c.inRange <= seg.inBytes);
    CHECK(c.outOffset + c.outRange <= seg.outBytes);
    CHECK(c.inOffset == (c.firstRecord - seg.firstRecord) * inStride * 4);
  }
  CHECK(next == count);
  for (const Segment& seg : plan.segments) {
    CHECK(seg.inBytes <= limits.maxSegmentBytes);
    CHECK(seg.outBytes <= limits.maxSegmentBytes);
  }

  SECTION("a record cap below one alignment granule still gives aligned chunks") {
    limits.recordCap = 1;  // 256-byte alignment of 12-byte records needs multiples of 64
    const ChunkPlan capped = planChunks(1000, inStride, outStride, limits);
    CHECK(capped.recordsPerChunk == 64);
    for (const Chunk& c : capped.chunks) CHECK(c.inOffset % limits.offsetAlignment == 0);
  }
  SECTION("zero strides bind four dummy bytes") {
    const ChunkPlan zero = planChunks(10, 0, 1, limits);
    REQUIRE(zero.chunks.size() == 1);
    CHECK(zero.chunks[0].inRange == 4);
    CHECK(zero.segments[0].inBytes == 4);
  }
  SECTION("an empty run has no chunks") { CHECK(planChunks(0, 3, 5, limits).chunks.empty()); }
  SECTION("a record larger than a binding is an error") {
    CHECK_THROWS_AS(planChunks(10, 1 << 15, 1, limits), HarnessError);
  }
}
