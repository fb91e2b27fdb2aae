// Checks a GPU LUT. A quadrature table (samples == 0, the default) is judged against the
// exact integrals (the adaptive references, lut_reference.hpp quadrature()) with the accuracy
// it promises: channels 0 and 1 within kExactAbsBound, channel 2 within kClothRelBound
// relative (plus kClothAbsFloor). A Hammersley table is judged against (a) the CPU evaluation
// of the identical sum, within the derived fp32 bound, and compared with (b) the exact
// integrals (reported, not judged: that difference is the Monte-Carlo error of the chosen
// sample count).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/progress_sink.hpp"
#include "library/shader_library.hpp"
#include "lut/dfg_lut.hpp"

namespace mb::lut {

struct ChannelError {
  double maxAbs = 0;
  double meanAbs = 0;
  double maxRel = 0;  // max |error| / max(|exact|, kClothAbsFloor); filled against the exact integrals
};

inline constexpr double kExactAbsBound = 1e-4;
inline constexpr double kClothRelBound = 1e-3;
// Cloth values below ~1e-7 are below the fp32 resolution of the albedos a shader adds them to;
// there the bound is absolute.
inline constexpr double kClothAbsFloor = 1e-7;

struct LutCheck {
  uint64_t texels = 0;  // texels compared
  std::array<ChannelError, kChannels> sameSum{}, quadrature{};
  std::array<double, kChannels> maxBound{};  // largest per-texel bound (fp32 bound, or the accuracy promised)
  double maxBoundRatio = 0;                  // max |gpu - judged value| / bound; <= 1 passes
  int64_t worstTexel = -1;                   // storage index (j * size + i) of maxBoundRatio
  uint64_t failures = 0;                     // values outside their bound
  uint64_t nonFinite = 0;                    // NaN or Inf GPU values
  bool withQuadrature = false;
  double cpuMs = 0;
  bool passed() const { return failures == 0 && nonFinite == 0; }
};

// Indices checked along each axis: all of them when grid is 0 or >= size, else `grid`
// indices spread evenly from 0 to size - 1 (both ends included).
std::vector<uint32_t> checkIndices(uint32_t size, uint32_t grid);

// Runs the CPU side on the texels of checkIndices() x checkIndices(), on every core: the same
// sum of the library's lutBricks and, when asked, the quadrature.
LutCheck checkLut(const ShaderLibrary& lib, const LutTable& gpu, uint32_t grid, bool withQuadrature,
                  ProgressSink* progress = nullptr);

}  // namespace mb::lut
