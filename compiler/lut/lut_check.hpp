// Checks a GPU LUT against (a) the CPU evaluation of the identical sum, within the derived
// fp32 bound, and (b) the high-accuracy quadrature of the integrals it estimates (reported,
// not judged: that difference is the Monte-Carlo error of the chosen sample count).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "lut/dfg_lut.hpp"

namespace mb::lut {

struct ChannelError {
  double maxAbs = 0;
  double meanAbs = 0;
};

struct LutCheck {
  uint64_t texels = 0;  // texels compared
  std::array<ChannelError, kChannels> sameSum{}, quadrature{};
  std::array<double, kChannels> maxBound{};  // largest per-texel fp32 bound
  double maxBoundRatio = 0;  // max |gpu - same sum| / bound; <= 1 passes
  int64_t worstTexel = -1;   // storage index (j * size + i) of maxBoundRatio
  uint64_t failures = 0;     // values outside their bound
  uint64_t nonFinite = 0;    // NaN or Inf GPU values
  bool withQuadrature = false;
  double cpuMs = 0;
  bool passed() const { return failures == 0 && nonFinite == 0; }
};

// Indices checked along each axis: all of them when grid is 0 or >= size, else `grid`
// indices spread evenly from 0 to size - 1 (both ends included).
std::vector<uint32_t> checkIndices(uint32_t size, uint32_t grid);

// Runs the CPU side on the texels of checkIndices() x checkIndices(), on every core.
LutCheck checkLut(const LutTable& gpu, uint32_t grid, bool withQuadrature);

}  // namespace mb::lut
