#include "preview/preview_image.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "write/package_writer.hpp"

namespace mb::preview {

uint8_t encodeSrgb8(double linear) {
  if (!(linear > 0.0)) return 0;  // also NaN
  if (linear >= 1.0) return 255;
  const double v = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
  return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

void heatmapColor(double e, uint8_t rgb[3]) {
  if (!(e <= 1.0)) {  // outside the tolerance, or NaN
    rgb[0] = 255, rgb[1] = 0, rgb[2] = 255;
    return;
  }
  // Stops at s = sqrt(e) = 0, 0.25, 0.5, 0.75, 1: black, blue, cyan, green, yellow.
  static constexpr double kStops[5][3] = {{0, 0, 0}, {0, 0, 255}, {0, 255, 255}, {0, 255, 0}, {255, 255, 0}};
  const double s = std::sqrt(std::max(e, 0.0)) * 4.0;
  const int i = std::min(static_cast<int>(s), 3);
  const double t = s - i;
  for (int c = 0; c < 3; ++c)
    rgb[c] = static_cast<uint8_t>(std::lround(kStops[i][c] + (kStops[i + 1][c] - kStops[i][c]) * t));
}

void writePng(const std::filesystem::path& file, const Image8& image) {
  PackageWriter::writeFileAtomically(file, encodePng(image));
}

}  // namespace mb::preview
