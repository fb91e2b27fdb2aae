// The DFG lookup table as data (DESIGN.md "DFG LUT convention", Filament's; docs/lut.md):
// texel (i, j) of a size x size table sits at its centre, NoV = (i + 0.5) / size and
// perceptual roughness = (j + 0.5) / size; alpha = perceptualRoughness^2. Storage is row-major
// with row j = roughness index, so row 0 is the SMOOTHEST row (it is what a sampler sees at
// t = 0 when the rows are uploaded in order), and the three channels are interleaved:
//   channel 0 = Int Gv Fc, channel 1 = Int Gv, channel 2 = cloth (Charlie D, Ashikhmin V).
// Seed 000 stores channels 0 and 1 the other way round; we follow Filament so that engines can
// swap LUTs.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mb::lut {

inline constexpr uint32_t kChannels = 3;
inline constexpr uint32_t kChannelGvFc = 0;
inline constexpr uint32_t kChannelGv = 1;
inline constexpr uint32_t kChannelCloth = 2;
inline constexpr const char* kChannelNames[kChannels] = {"dfg_gv_fc", "dfg_gv", "cloth"};

// Accepted ranges (docs/cli.md): 4096^2 texels x 12 bytes is the largest table we stage, and
// sample indices must be exact in fp32 (the Hammersley brick takes the index as a float).
inline constexpr uint32_t kMaxSize = 4096;
inline constexpr uint32_t kMaxSamples = 1u << 24;

// Texel-centre coordinate of index k in a table of `size` texels.
inline double texelCentre(uint32_t k, uint32_t size) { return (k + 0.5) / size; }

struct LutTable {
  uint32_t size = 0;
  uint32_t samples = 0;       // Hammersley samples per texel; 0: deterministic quadrature
  std::vector<float> values;  // size * size * kChannels, layout above
  float at(uint32_t i, uint32_t j, uint32_t channel) const {
    return values[(static_cast<size_t>(j) * size + i) * kChannels + channel];
  }
};

// The kernel's input records: (NoV, perceptual roughness) per texel in storage order, as the
// fp32 values the GPU sees (the CPU check reads the same floats back).
std::vector<float> texelInputs(uint32_t size);

// The same table in double, as `bench` measures a LUT's error against the split-sum integral
// (bench_engine/ibl_bench.hpp): channels 0 and 1 only (x = Int Gv Fc, y = Int Gv) from the
// quadrature in shaderlib/common/ibl_reference.hpp, in two planes, rounded to the storage
// format, and read with bilinear filtering and clamp-to-edge emulated in double from the
// rounded texels (a GPU sampler additionally rounds the fractional position to 8 bits on most
// hardware, which this leaves out).
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

}  // namespace mb::lut
