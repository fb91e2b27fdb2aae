// IEEE 754 binary16 conversion for the fp16 LUT outputs (round to nearest, ties to even, as a
// GPU converting to R16G16B16A16_SFLOAT does).
#pragma once
#include <cstdint>

namespace mb::lut {

uint16_t floatToHalf(float value);
float halfToFloat(uint16_t bits);

}  // namespace mb::lut
