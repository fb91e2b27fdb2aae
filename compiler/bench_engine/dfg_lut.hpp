// The DFG lookup-table choice for image-based lighting (DESIGN.md "DFG LUT convention",
// Filament's layout): u = n.v, v = perceptual roughness, texel (i, j) at the centre
// ((i + 0.5)/size, (j + 0.5)/size); channel x = Int Gv Fc, y = Int Gv, from the split-sum
// quadrature in shaderlib/common/ibl_reference.hpp, stored as RG16F or RG32F.
//
// The error of a LUT is measured on the CPU: bilinear filtering with clamp-to-edge is
// emulated in double from the quantized texels (a GPU sampler additionally rounds the
// fractional position to 8 bits on most hardware, which this leaves out). The harness binds
// storage buffers only, so a LUT's cost is given as its size in bytes, not in ns.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace mb::bench {

enum class LutFormat { Fp16, Fp32 };
std::string lutFormatName(LutFormat f);  // "fp16" / "fp32"

struct DfgLut {
  uint32_t size = 0;
  std::vector<double> x, y;  // texel (i = n.v, j = roughness) at [j * size + i]
  uint64_t bytes(LutFormat f) const { return uint64_t{size} * size * 2 * (f == LutFormat::Fp16 ? 2 : 4); }
};

// In double, at texel centres.
DfgLut buildDfgLut(uint32_t size);
// Every texel rounded to the storage format (round to nearest even).
DfgLut quantize(const DfgLut& lut, LutFormat format);
// IEEE binary16 rounding (nearest even, subnormals kept, overflow to infinity), as a double.
double roundToHalf(double value);

struct DfgSample {
  double x = 0, y = 0;
};
// Bilinear filtering with clamp-to-edge at (u, v) in [0, 1]^2.
DfgSample sampleBilinear(const DfgLut& lut, double u, double v);

}  // namespace mb::bench
