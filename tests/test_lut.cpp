// matbricks lut: the DFG LUT generated on the GPU against the CPU evaluation of the same sum
// and the quadrature; layout (row and channel order); every output format read back; the
// command line's errors.
#include <catch2/catch.hpp>

#include <bit>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

#include "compile/glsl_compiler.hpp"
#include "lut/half_float.hpp"
#include "lut/ktx2.hpp"
#include "lut/lut_check.hpp"
#include "lut/lut_formats.hpp"
#include "lut/lut_gpu.hpp"
#include "lut/lut_reference.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"

using namespace mb;
using namespace mb::lut;
namespace fs = std::filesystem;

namespace {

constexpr uint32_t kTestSize = 16, kTestSamples = 64;

// A table made by the default estimator (deterministic quadrature) on the test device.
GpuLut quadratureLut(uint32_t size) {
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  GpuLut l = generateDfgLutOnGpu(gpu, test::shippedLibrary(), size, 0);
  REQUIRE(gpu.validationMessages().empty());
  return l;
}

// One small Hammersley LUT generated on the test device, shared by the cases below.
const GpuLut& smallLut() {
  static const GpuLut lut = [] {
    harness::VulkanHarness gpu(harness::testDeviceOptions());
    GpuLut l = generateDfgLutOnGpu(gpu, test::shippedLibrary(), kTestSize, kTestSamples);
    REQUIRE(gpu.validationMessages().empty());
    return l;
  }();
  return lut;
}

uint32_t le32(const std::string& s, size_t at) {
  uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(s.at(at + k));
  return v;
}
uint64_t le64(const std::string& s, size_t at) { return le32(s, at) | (uint64_t(le32(s, at + 4)) << 32); }
uint16_t le16(const std::string& s, size_t at) {
  return static_cast<uint16_t>(static_cast<unsigned char>(s.at(at)) | (static_cast<unsigned char>(s.at(at + 1)) << 8));
}

fs::path tempPath(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("mb_lut_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

}  // namespace

TEST_CASE("GPU DFG LUT equals the CPU evaluation of the identical sum within the fp32 bound", "[lut][vulkan]") {
  const GpuLut& lut = smallLut();
  REQUIRE(lut.table.values.size() == kTestSize * kTestSize * kChannels);
  LutCheck check = checkLut(test::shippedLibrary(), lut.table, 0, false);
  INFO("max error / bound " << check.maxBoundRatio << " at texel " << check.worstTexel);
  CHECK(check.texels == kTestSize * kTestSize);
  CHECK(check.nonFinite == 0);
  CHECK(check.failures == 0);
  CHECK(check.passed());
  // The bound is tight enough to matter: a 1e-4 relative change of one value breaks it.
  LutTable broken = lut.table;
  broken.values[(5 * kTestSize + 9) * kChannels + kChannelGv] *= 1.0f + 1e-4f;
  CHECK(checkLut(test::shippedLibrary(), broken, 0, false).failures == 1);
}

TEST_CASE(
    "the quadrature DFG LUT is within 1e-4 (channels 0, 1) and 1e-3 relative (cloth) of the exact integrals at every texel",
    "[lut][vulkan]") {
  // Every texel of 16^2 and 64^2 tables, the grazing column and the smoothest rows included;
  // larger tables are measured by bench/bench_lut.cpp (docs/lut.md).
  for (uint32_t size : {16u, 64u}) {
    const GpuLut lut = quadratureLut(size);
    const LutCheck check = checkLut(test::shippedLibrary(), lut.table, 0, true);
    INFO(size << "^2: max error / bound " << check.maxBoundRatio << " at texel " << check.worstTexel << "; max abs "
              << check.quadrature[0].maxAbs << ", " << check.quadrature[1].maxAbs << ", cloth max rel "
              << check.quadrature[2].maxRel);
    CHECK(check.texels == size * size);
    CHECK(check.nonFinite == 0);
    CHECK(check.failures == 0);
    CHECK(check.quadrature[kChannelGvFc].maxAbs <= kExactAbsBound);
    CHECK(check.quadrature[kChannelGv].maxAbs <= kExactAbsBound);
    CHECK(check.quadrature[kChannelCloth].maxRel <= kClothRelBound);
    if (size != 16) continue;
    // The check judges: one value moved by the bound fails it, in each channel.
    for (uint32_t c = 0; c < kChannels; ++c) {
      LutTable broken = lut.table;
      float& value = broken.values[(3 * size + 0) * kChannels + c];
      value += c == kChannelCloth ? 2.0f * float(kClothRelBound) * value + 1e-6f : 2.0f * float(kExactAbsBound);
      CHECK(checkLut(test::shippedLibrary(), broken, 0, true).failures == 1);
    }
  }
}

TEST_CASE("the quadrature kernel computes the rule that mb_bench_lut_rule measures in double", "[lut][vulkan]") {
  // The node counts are chosen from the double evaluation of the rule (evaluateQuadratureRule,
  // bench/bench_lut_rule.cpp); this ties it to the kernel: the GPU table differs from it by
  // fp32 rounding only, far below the quadrature errors that separate the candidate rules
  // (~1e-5 absolute and up; docs/lut.md). Changing any node count moves values by more.
  const GpuLut lut = quadratureLut(16);
  const std::vector<float> inputs = texelInputs(16);
  double worstAbs = 0, worstRel = 0;
  for (uint32_t t = 0; t < 16 * 16; ++t) {
    const auto rule = evaluateQuadratureRule({}, inputs[2 * t], inputs[2 * t + 1]);
    for (uint32_t c = 0; c < kChannels; ++c) {
      const double d = std::abs(lut.table.values[3 * t + c] - rule[c]);
      if (c == kChannelCloth)
        worstRel = std::max(worstRel, d / std::max(std::abs(rule[c]), kClothAbsFloor));
      else
        worstAbs = std::max(worstAbs, d);
    }
  }
  INFO("GPU - double rule: channels 0/1 max abs " << worstAbs << ", cloth max rel " << worstRel);
  CHECK(worstAbs < 2e-6);
  CHECK(worstRel < 2e-5);
  // The comparison separates rules: one count lower moves the table by more than that.
  QuadratureRule coarser;
  coarser.ggxPartialOuter = 12;
  double moved = 0;
  for (uint32_t t = 0; t < 16 * 16; ++t)
    moved = std::max(moved, std::abs(evaluateQuadratureRule(coarser, inputs[2 * t], inputs[2 * t + 1])[kChannelGv] -
                                     lut.table.values[3 * t + kChannelGv]));
  INFO("ggxPartialOuter 12 instead of 16 moves channel 1 by up to " << moved);
  CHECK(moved > 1e-5);
}

TEST_CASE("the quadrature kernel meets the bounds at the extreme texels of 1024^2 and 4096^2 tables", "[lut][vulkan]") {
  // The grazing column and the smoothest rows of the largest tables (alpha down to
  // (0.5/4096)^2 = 1.5e-8), run as single records without generating the whole table.
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  EmittedShader shader = emitDfgQuadratureKernel(test::shippedLibrary());
  auto kernel = gpu.createKernel(compileComputeGlsl(shader.glsl, shader.fileName).spirv);
  std::vector<float> records;
  for (uint32_t size : {1024u, 4096u})
    for (auto [i, j] :
         {std::pair{0u, 0u}, {0u, 1u}, {1u, 0u}, {0u, size / 2}, {size / 2, 0u}, {0u, size - 1}, {size - 1, 0u}}) {
      records.push_back(static_cast<float>(texelCentre(i, size)));
      records.push_back(static_cast<float>(texelCentre(j, size)));
    }
  const uint32_t count = static_cast<uint32_t>(records.size() / 2);
  harness::RunResult run = gpu.run(*kernel, records, 2, 3, count);
  REQUIRE(gpu.validationMessages().empty());
  for (uint32_t k = 0; k < count; ++k) {
    const auto exact = quadrature(records[2 * k], records[2 * k + 1]);
    for (uint32_t c = 0; c < kChannels; ++c) {
      const double g = run.outputs[3 * k + c],
                   bound = c == kChannelCloth ? kClothRelBound * std::abs(exact[c]) + kClothAbsFloor : kExactAbsBound;
      INFO("n.v " << records[2 * k] << " roughness " << records[2 * k + 1] << " channel " << c << ": GPU " << g
                  << " exact " << exact[c]);
      CHECK(std::abs(g - exact[c]) <= bound);
    }
  }
}

TEST_CASE("DFG LUT rows run from smooth to rough and channels are Gv*Fc, Gv, cloth", "[lut][vulkan]") {
  const LutTable& t = smallLut().table;
  const uint32_t last = kTestSize - 1;
  // Row 0, last column: perceptual roughness 1/32 and n.v = 31/32: a near-mirror lobe keeps
  // all its energy (Int Gv ~ 1) and Fc = (1 - v.h)^5 ~ (1/32)^5 ~ 3e-8 (Int Gv Fc ~ 0).
  CHECK(t.at(last, 0, kChannelGv) > 0.99f);
  CHECK(t.at(last, 0, kChannelGvFc) < 1e-4f);
  // The roughest row loses energy to single scattering; grazing views see more Fresnel.
  CHECK(t.at(last, last, kChannelGv) < 0.9f);
  CHECK(t.at(0, last, kChannelGvFc) > t.at(last, last, kChannelGvFc));
  // Cloth albedo of a rough sheen lobe at normal incidence is well inside (0, 1).
  CHECK(t.at(last, last, kChannelCloth) > 0.05f);
  CHECK(t.at(last, last, kChannelCloth) < 1.0f);
}

TEST_CASE("the CPU same sum converges to the quadrature of the exact integrals", "[lut]") {
  // Two independent computations of the same three integrals: Filament's estimators with
  // 4096 Hammersley points, and deterministic quadrature (ibl_reference.hpp and
  // cloth_dfg_reference.hpp). A wrong normalization (the 4, the 2 pi) would show as O(1).
  const SameSum sameSum(lutBricks(test::shippedLibrary()));
  for (auto [NoV, rough] : {std::pair{0.5f, 0.5f}, {0.9f, 0.7f}, {0.25f, 0.35f}, {0.75f, 1.0f}}) {
    TexelSum s = sameSum.evaluate(NoV, rough, 4096);
    auto q = quadrature(NoV, rough);
    for (uint32_t c = 0; c < kChannels; ++c) {
      INFO("NoV " << NoV << " roughness " << rough << " channel " << c << ": sum " << s.value[c] << " quadrature "
                  << q[c]);
      CHECK(std::abs(s.value[c] - q[c]) < 2e-3);
    }
  }
}

TEST_CASE("fp16 conversion rounds to nearest even", "[lut]") {
  CHECK(floatToHalf(1.0f) == 0x3c00);
  CHECK(floatToHalf(-2.0f) == 0xc000);
  CHECK(floatToHalf(65504.0f) == 0x7bff);
  CHECK(floatToHalf(65520.0f) == 0x7c00);                          // rounds up to inf
  CHECK(floatToHalf(std::ldexp(1.0f, -24)) == 0x0001);             // smallest subnormal
  CHECK(floatToHalf(std::ldexp(1.0f, -25)) == 0x0000);             // tie to even: 0
  CHECK(floatToHalf(1.0f + std::ldexp(1.0f, -11)) == 0x3c00);      // tie to even: down
  CHECK(floatToHalf(1.0f + 3 * std::ldexp(1.0f, -11)) == 0x3c02);  // tie to even: up
  CHECK(floatToHalf(0.1f) == 0x2e66);
  for (uint32_t h = 0; h < 0x7c00; ++h) REQUIRE(floatToHalf(halfToFloat(static_cast<uint16_t>(h))) == h);
}

TEST_CASE("raw LUT layout: little-endian, row-major from the smoothest row, channels interleaved", "[lut][vulkan]") {
  const LutTable& t = smallLut().table;
  for (lut::Precision p : {lut::Precision::Fp32, lut::Precision::Fp16}) {
    const std::string raw = encodeLut(t, OutputFormat::Raw, p);
    const size_t bytes = p == lut::Precision::Fp32 ? 4 : 2;
    REQUIRE(raw.size() == kTestSize * kTestSize * kChannels * bytes);
    for (uint32_t j = 0; j < kTestSize; ++j)
      for (uint32_t i = 0; i < kTestSize; ++i)
        for (uint32_t c = 0; c < kChannels; ++c) {
          size_t at = ((size_t(j) * kTestSize + i) * kChannels + c) * bytes;
          float v = p == lut::Precision::Fp32 ? std::bit_cast<float>(le32(raw, at)) : halfToFloat(le16(raw, at));
          REQUIRE(v == storedValue(t.at(i, j, c), p));
        }
  }
}

TEST_CASE("KTX2 LUT parses back: identifier, header, index, DFD, key/values, texels", "[lut][vulkan]") {
  const LutTable& t = smallLut().table;
  for (lut::Precision p : {lut::Precision::Fp32, lut::Precision::Fp16}) {
    const std::string f = encodeLut(t, OutputFormat::Ktx2, p);
    const uint32_t bits = p == lut::Precision::Fp32 ? 32 : 16, texelBytes = 4 * bits / 8;
    const char id[12] = {'\xAB', 'K', 'T', 'X', ' ', '2', '0', '\xBB', '\r', '\n', '\x1A', '\n'};
    REQUIRE(std::memcmp(f.data(), id, 12) == 0);
    CHECK(le32(f, 12) == (p == lut::Precision::Fp32 ? 109u : 97u));  // VK_FORMAT_R32G32B32A32/R16G16B16A16_SFLOAT
    CHECK(le32(f, 16) == bits / 8);                                  // typeSize
    CHECK(le32(f, 20) == kTestSize);
    CHECK(le32(f, 24) == kTestSize);
    CHECK(le32(f, 28) == 0);  // pixelDepth
    CHECK(le32(f, 32) == 0);  // layerCount
    CHECK(le32(f, 36) == 1);  // faceCount
    CHECK(le32(f, 40) == 1);  // levelCount
    CHECK(le32(f, 44) == 0);  // supercompressionScheme
    const uint32_t dfdOffset = le32(f, 48), dfdLength = le32(f, 52), kvdOffset = le32(f, 56), kvdLength = le32(f, 60);
    CHECK(le64(f, 64) == 0);  // sgd
    CHECK(le64(f, 72) == 0);
    const uint64_t levelOffset = le64(f, 80), levelLength = le64(f, 88);
    CHECK(le64(f, 96) == levelLength);
    CHECK(dfdOffset == kKtx2HeaderBytes + kKtx2LevelIndexBytes);
    CHECK(kvdOffset == dfdOffset + dfdLength);
    CHECK(levelOffset % texelBytes == 0);
    CHECK(levelOffset >= kvdOffset + kvdLength);
    REQUIRE(levelLength == size_t(kTestSize) * kTestSize * texelBytes);
    REQUIRE(levelOffset + levelLength == f.size());
    // DFD: total size, then one basic block of 4 samples.
    CHECK(le32(f, dfdOffset) == dfdLength);
    CHECK(dfdLength == 4 + 24 + 4 * 16);
    CHECK(le32(f, dfdOffset + 4) == 0);                         // Khronos, basic format
    CHECK(le32(f, dfdOffset + 8) == (2u | (88u << 16)));        // version 1.3, block size
    CHECK((le32(f, dfdOffset + 12) & 0xffffffu) == 0x010101u);  // RGBSDA, BT709, linear
    CHECK((le32(f, dfdOffset + 20) & 0xffu) == texelBytes);     // bytesPlane0
    const uint32_t channelIds[4] = {0, 1, 2, 15};
    for (uint32_t s = 0; s < 4; ++s) {
      size_t at = dfdOffset + 28 + 16 * s;
      CHECK((le32(f, at) & 0xffffu) == s * bits);             // bitOffset
      CHECK(((le32(f, at) >> 16) & 0xffu) == bits - 1);       // bitLength - 1
      CHECK((le32(f, at) >> 24) == (channelIds[s] | 0xc0u));  // channel | SIGNED | FLOAT
      CHECK(le32(f, at + 8) == 0xBF800000u);
      CHECK(le32(f, at + 12) == 0x3F800000u);
    }
    // Key/value data: sorted keys, each entry padded to 4 bytes.
    std::vector<std::string> keys;
    for (size_t at = kvdOffset; at < kvdOffset + kvdLength;) {
      uint32_t len = le32(f, at);
      keys.push_back(std::string(f.c_str() + at + 4));
      at += 4 + (len + 3) / 4 * 4;
    }
    CHECK(keys == std::vector<std::string>{"KTXorientation", "KTXwriter"});
    for (uint32_t j = 0; j < kTestSize; ++j)
      for (uint32_t i = 0; i < kTestSize; ++i)
        for (uint32_t c = 0; c < 4; ++c) {
          size_t at = levelOffset + (size_t(j) * kTestSize + i) * texelBytes + c * (bits / 8);
          float v = bits == 32 ? std::bit_cast<float>(le32(f, at)) : halfToFloat(le16(f, at));
          REQUIRE(v == (c < kChannels ? storedValue(t.at(i, j, c), p) : 1.0f));
        }
  }
}

TEST_CASE("CSV LUT reads back with texel-centre coordinates", "[lut][vulkan]") {
  const LutTable& t = smallLut().table;
  std::istringstream in(encodeLut(t, OutputFormat::Csv, lut::Precision::Fp32));
  std::string line;
  std::getline(in, line);
  CHECK(line.rfind("#", 0) == 0);
  std::getline(in, line);
  CHECK(line == "nov,perceptual_roughness,dfg_gv_fc,dfg_gv,cloth");
  for (uint32_t j = 0; j < kTestSize; ++j)
    for (uint32_t i = 0; i < kTestSize; ++i) {
      REQUIRE(std::getline(in, line));
      double nov, rough;
      float c0, c1, c2;
      REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%f,%f,%f", &nov, &rough, &c0, &c1, &c2) == 5);
      CHECK(nov == Approx((i + 0.5) / kTestSize).epsilon(1e-9));
      CHECK(rough == Approx((j + 0.5) / kTestSize).epsilon(1e-9));
      REQUIRE(c0 == t.at(i, j, 0));
      REQUIRE(c1 == t.at(i, j, 1));
      REQUIRE(c2 == t.at(i, j, 2));
    }
  CHECK_FALSE(std::getline(in, line));
}

TEST_CASE("C header LUT has its size constants and every value", "[lut][vulkan]") {
  const LutTable& t = smallLut().table;
  const std::string h = encodeLut(t, OutputFormat::Header, lut::Precision::Fp32);
  CHECK(h.find("#define MB_DFG_LUT_SIZE 16\n") != std::string::npos);
  CHECK(h.find("#define MB_DFG_LUT_CHANNELS 3\n") != std::string::npos);
  CHECK(h.find("#define MB_DFG_LUT_SAMPLES 64 ") != std::string::npos);
  size_t at = h.find("static const float mb_dfg_lut[MB_DFG_LUT_SIZE * MB_DFG_LUT_SIZE * MB_DFG_LUT_CHANNELS] = {\n");
  REQUIRE(at != std::string::npos);
  const char* p = h.c_str() + h.find('\n', at) + 1;
  for (size_t k = 0; k < t.values.size(); ++k) {
    char* end = nullptr;
    float v = std::strtof(p, &end);
    REQUIRE(end != p);
    REQUIRE(*end == 'f');
    REQUIRE(v == t.values[k]);
    p = end + 1;
    while (*p == ',' || *p == ' ' || *p == '\n') ++p;
  }
  CHECK(std::string(p) == "};\n");
  const std::string h16 = encodeLut(t, OutputFormat::Header, lut::Precision::Fp16);
  CHECK(h16.find("static const uint16_t mb_dfg_lut[") != std::string::npos);
}

TEST_CASE("matbricks lut writes the file its extension names and reports in JSON", "[lut][cli][vulkan]") {
  fs::path out = tempPath("dfg.ktx2");
  fs::remove(out);
  auto r = test::runCli("lut --size 8 --samples 32 --check-grid 4 --format fp16 --json -o " + out.string());
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  auto j = nlohmann::json::parse(r.output);
  CHECK(j["passed"] == true);
  CHECK(j["output_format"] == "ktx2");
  CHECK(j["checked_texels"] == 16);
  CHECK(j["estimator"] == "hammersley");
  CHECK(j["judged_against"] == "same_sum");
  CHECK(j["check"]["failures"] == 0);
  CHECK(j["gpu_ms"].get<double>() > 0.0);
  // 32 samples: a Monte-Carlo error of ~0.16 at the smoothest grazing texels; a wrong
  // normalization would be O(1).
  CHECK(j["vs_quadrature"]["channels"]["dfg_gv"]["max_abs"].get<double>() > 0.0);
  CHECK(j["vs_quadrature"]["channels"]["dfg_gv"]["max_abs"].get<double>() < 0.5);
  std::string f = test::readFile(out);
  REQUIRE(f.size() > 80);
  CHECK(le32(f, 12) == 97u);  // fp16 -> R16G16B16A16_SFLOAT
  // The default estimator is the quadrature, judged against the exact integrals.
  r = test::runCli("lut --size 8 --check-grid 0 --json");
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  j = nlohmann::json::parse(r.output);
  CHECK(j["estimator"] == "quadrature");
  CHECK(j["judged_against"] == "exact");
  CHECK(j["check"]["failures"] == 0);
  CHECK(j["vs_quadrature"]["channels"]["dfg_gv"]["max_abs"].get<double>() <= 1e-4);
  fs::remove_all(out.parent_path());
}

TEST_CASE("matbricks lut rejects bad options with the documented exit codes and writes nothing",
          "[lut][cli][diagnostics]") {
  fs::path out = tempPath("bad.bin");
  fs::remove(out);
  auto r = test::runCli("lut --size 0 -o " + out.string());
  CHECK(r.exitCode == 2);
  r = test::runCli("lut --size 8 --output-format png -o " + out.string());
  CHECK(r.exitCode == 2);
  r = test::runCli("lut --size 8 --format fp64 -o " + out.string());
  CHECK(r.exitCode == 2);
  fs::path unknownExtension = tempPath("lut.png");
  r = test::runCli("lut --size 8 -o " + unknownExtension.string());
  CHECK(r.exitCode == 2);
  CHECK_FALSE(fs::exists(unknownExtension));
  CHECK_FALSE(fs::exists(out));
  fs::path unwritable = tempPath("missing_dir") / "lut.bin";
  r = test::runCli("lut --size 8 --samples 16 -o " + unwritable.string());
  CHECK(r.exitCode == 3);
  CHECK_THAT(r.output, Catch::Contains(unwritable.string() + ": error[E-IO]: "));
  CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(unwritable.parent_path()));
  fs::remove_all(out.parent_path());
}
