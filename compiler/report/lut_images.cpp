#include "report/lut_images.hpp"

namespace mb::report {

Image8 lutRgbImage(const lut::LutTable& t) {
  Image8 im{t.size, t.size, lut::kChannels, {}};
  im.pixels.reserve(t.values.size());
  for (float v : t.values) im.pixels.push_back(toByte(v));  // storage order is the image's order
  return im;
}

Image8 lutChannelImage(const lut::LutTable& t, uint32_t channel) {
  Image8 im{t.size, t.size, 1, {}};
  im.pixels.reserve(size_t(t.size) * t.size);
  for (uint32_t j = 0; j < t.size; ++j)
    for (uint32_t i = 0; i < t.size; ++i) im.pixels.push_back(toByte(t.at(i, j, channel)));
  return im;
}

}  // namespace mb::report
