// The preview's pictures: display encoding (a tonemap brick, then the sRGB OETF), the
// difference heatmap, and PNG files written with stb_image_write (Debian libstb-dev).
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "write/png_image.hpp"

namespace mb::preview {

// The preview's pictures are 8-bit RGB (channels 3), row 0 at the top.
using mb::Image8;
using mb::encodePng;

// The sRGB OETF (IEC 61966-2-1: 12.92 x below 0.0031308, else 1.055 x^(1/2.4) - 0.055) of a
// display-referred linear value, clamped to [0, 1] and rounded to 8 bits.
uint8_t encodeSrgb8(double linear);

// The heatmap colour of e = |gpu - reference| / allowed error (docs/preview.md "Difference
// image"): black at 0, then blue, cyan, green and yellow as e rises towards 1 (a piecewise
// linear ramp over e^(1/2), so small errors stay visible), and saturated magenta for e > 1 (a
// pixel outside the tolerance). Background pixels are drawn in dark grey by the caller.
void heatmapColor(double e, uint8_t rgb[3]);

// encodePng, written atomically (write/package_writer.hpp).
void writePng(const std::filesystem::path& file, const Image8& image);

}  // namespace mb::preview
