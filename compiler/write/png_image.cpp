#include "write/png_image.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cmath>
#include <stdexcept>

namespace mb {
namespace {

void appendBytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
}

}  // namespace

std::string encodePng(const Image8& im) {
  const size_t expected = size_t(im.width) * im.height * im.channels;
  if (im.width == 0 || im.height == 0 || im.channels == 0 || im.channels > 4 || im.pixels.size() != expected)
    throw std::runtime_error("encodePng: inconsistent image");
  std::string out;
  const int stride = int(im.width * im.channels);
  if (!stbi_write_png_to_func(appendBytes, &out, int(im.width), int(im.height), int(im.channels), im.pixels.data(),
                              stride))
    throw std::runtime_error("encodePng: stb_image_write failed");
  return out;
}

Image8 decodePng(const std::string& bytes) {
  int w = 0, h = 0, n = 0;
  unsigned char* data =
      stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &w, &h, &n, 0);
  if (!data) throw std::runtime_error(std::string("decodePng: ") + stbi_failure_reason());
  Image8 im{uint32_t(w), uint32_t(h), uint32_t(n), {}};
  im.pixels.assign(data, data + size_t(w) * h * n);
  stbi_image_free(data);
  return im;
}

uint8_t toByte(double v) {
  if (!(v > 0)) return 0;
  if (v >= 1) return 255;
  return uint8_t(std::lround(v * 255.0));
}

}  // namespace mb
