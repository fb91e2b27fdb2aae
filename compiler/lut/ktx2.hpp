// KTX 2.0 container for one uncompressed 2D image (Khronos KTX File Format Specification 2.0):
// identifier, header, index, one level, the Basic Data Format Descriptor (Khronos Data Format
// Specification 1.3), key/value data (KTXorientation, KTXwriter), then the level's texels.
// Little-endian throughout, as the specification requires.
#pragma once
#include <cstdint>
#include <string>

namespace mb::lut {

inline constexpr uint32_t kVkFormatR16G16B16A16Sfloat = 97;
inline constexpr uint32_t kVkFormatR32G32B32A32Sfloat = 109;

struct Ktx2Image {
  uint32_t vkFormat = kVkFormatR32G32B32A32Sfloat;  // one of the two above
  uint32_t width = 0, height = 0;
  std::string texels;  // width * height texels, RGBA, rows in order (row 0 first)
  std::string writer;  // value of the KTXwriter key
};

std::string encodeKtx2(const Ktx2Image& image);

// Byte offsets of the fixed-size parts (also what tests parse back).
inline constexpr size_t kKtx2HeaderBytes = 80;      // identifier 12 + header 36 + index 32
inline constexpr size_t kKtx2LevelIndexBytes = 24;  // per level: offset, length, uncompressed length

}  // namespace mb::lut
