// PNG encoding and decoding through stb_image_write and stb_image (Debian libstb-dev, whose
// libstb.so holds their implementations). Images are encoded in memory and written by
// PackageWriter (a report, a preview directory) or atomically (a preview .png), so nothing is
// ever half-written.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace mb {

struct Image8 {
  uint32_t width = 0, height = 0, channels = 0;  // channels: 1 (grey), 3 (RGB) or 4 (RGBA)
  std::vector<uint8_t> pixels;                   // row-major, top row first, interleaved
};

// Throws std::runtime_error if stb cannot encode it (empty or inconsistent image).
std::string encodePng(const Image8& image);
// Decodes PNG bytes; throws std::runtime_error with stb's reason when they are not a PNG.
Image8 decodePng(const std::string& bytes);

// A linear value in [0, 1] (clamped; NaN as 0) to 8 bits, rounded.
uint8_t toByte(double value);

}  // namespace mb
