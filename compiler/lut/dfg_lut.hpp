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

}  // namespace mb::lut
