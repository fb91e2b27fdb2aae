// The DFG LUT as pictures for the report: x = n.v from 0 (left) to 1 (right), y = perceptual
// roughness from 0 (top: storage row 0, the smoothest) to 1 (bottom), one pixel per texel.
// Values are linear in [0, 1], stored as 8 bits without a transfer curve, so a pixel's
// value / 255 is the texel's value (to 1/510).
#pragma once
#include <cstdint>

#include "lut/dfg_lut.hpp"
#include "write/png_image.hpp"

namespace mb::report {

// Channel 0 (Int Gv Fc) in red, 1 (Int Gv) in green, 2 (cloth) in blue.
Image8 lutRgbImage(const lut::LutTable& table);
// One channel in grey.
Image8 lutChannelImage(const lut::LutTable& table, uint32_t channel);

}  // namespace mb::report
