#include "lut/ktx2.hpp"

#include <map>
#include <stdexcept>

namespace mb::lut {
namespace {

void put32(std::string& out, uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xffu));
}
void put64(std::string& out, uint64_t v) {
  put32(out, static_cast<uint32_t>(v));
  put32(out, static_cast<uint32_t>(v >> 32));
}
void padTo(std::string& out, size_t alignment) {
  while (out.size() % alignment) out.push_back('\0');
}

// Basic descriptor block for 4 signed-float channels R, G, B, A of `bits` each.
std::string basicDfd(uint32_t bits) {
  constexpr uint32_t kSamples = 4, kBlockBytes = 24 + 16 * kSamples;
  constexpr uint32_t kModelRgbsda = 1, kPrimariesBt709 = 1, kTransferLinear = 1, kVersion13 = 2;
  constexpr uint32_t kSigned = 0x40, kFloat = 0x80;
  constexpr uint32_t kChannelIds[kSamples] = {0, 1, 2, 15};  // R, G, B, A in the RGBSDA model
  std::string d;
  put32(d, 4 + kBlockBytes);  // dfdTotalSize
  put32(d, 0);                // vendorId KHRONOS (17 bits), descriptorType BASICFORMAT (15 bits)
  put32(d, kVersion13 | (kBlockBytes << 16));
  put32(d, kModelRgbsda | (kPrimariesBt709 << 8) | (kTransferLinear << 16));  // flags: straight alpha
  put32(d, 0);                    // texelBlockDimension0..3 = 1x1x1x1 (stored minus one)
  put32(d, kSamples * bits / 8);  // bytesPlane0 = bytes per texel; planes 1..3 = 0
  put32(d, 0);                    // bytesPlane4..7
  for (uint32_t s = 0; s < kSamples; ++s) {
    put32(d, (s * bits) | ((bits - 1) << 16) | ((kChannelIds[s] | kSigned | kFloat) << 24));
    put32(d, 0);  // samplePosition0..3
    // Float samples give their range as 32-bit floats -1.0 and 1.0 whatever their width
    // (Khronos Data Format 1.3 sec. 5.18; libktx writes the same for 16-bit floats).
    put32(d, 0xBF800000u);
    put32(d, 0x3F800000u);
  }
  return d;
}

std::string keyValueData(const std::map<std::string, std::string>& kv) {
  std::string out;
  for (const auto& [key, value] : kv) {  // std::map: sorted by key bytes, as required
    std::string entry = key + '\0' + value + '\0';
    put32(out, static_cast<uint32_t>(entry.size()));
    out += entry;
    padTo(out, 4);
  }
  return out;
}

}  // namespace

std::string encodeKtx2(const Ktx2Image& image) {
  uint32_t bits = 0;
  if (image.vkFormat == kVkFormatR16G16B16A16Sfloat) bits = 16;
  if (image.vkFormat == kVkFormatR32G32B32A32Sfloat) bits = 32;
  if (bits == 0) throw std::logic_error("encodeKtx2: unsupported vkFormat");
  const uint32_t texelBytes = 4 * bits / 8;
  if (image.texels.size() != static_cast<size_t>(image.width) * image.height * texelBytes)
    throw std::logic_error("encodeKtx2: texel data does not match the image size");

  const std::string dfd = basicDfd(bits);
  const std::string kvd = keyValueData({{"KTXorientation", "rd"}, {"KTXwriter", image.writer}});
  const size_t dfdOffset = kKtx2HeaderBytes + kKtx2LevelIndexBytes;
  const size_t kvdOffset = dfdOffset + dfd.size();
  // Level data starts at a multiple of lcm(texel block size, 4) = the texel size (8 or 16).
  size_t levelOffset = kvdOffset + kvd.size();
  levelOffset = (levelOffset + texelBytes - 1) / texelBytes * texelBytes;

  std::string out = {'\xAB', 'K', 'T', 'X', ' ', '2', '0', '\xBB', '\r', '\n', '\x1A', '\n'};
  put32(out, image.vkFormat);
  put32(out, bits / 8);  // typeSize
  put32(out, image.width);
  put32(out, image.height);
  put32(out, 0);  // pixelDepth: a 2D image
  put32(out, 0);  // layerCount: not an array
  put32(out, 1);  // faceCount
  put32(out, 1);  // levelCount
  put32(out, 0);  // supercompressionScheme: none
  put32(out, static_cast<uint32_t>(dfdOffset));
  put32(out, static_cast<uint32_t>(dfd.size()));
  put32(out, static_cast<uint32_t>(kvdOffset));
  put32(out, static_cast<uint32_t>(kvd.size()));
  put64(out, 0);  // sgdByteOffset
  put64(out, 0);  // sgdByteLength
  put64(out, levelOffset);
  put64(out, image.texels.size());
  put64(out, image.texels.size());  // uncompressedByteLength
  out += dfd;
  out += kvd;
  out.resize(levelOffset, '\0');
  out += image.texels;
  return out;
}

}  // namespace mb::lut
