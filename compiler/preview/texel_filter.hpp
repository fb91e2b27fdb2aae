// Linear texture filtering in double as Vulkan defines it ("Texel Linear Filtering", "Texel
// Mipmap Filtering"), with the bound on how far a conforming device's fixed-point weights can
// move the filtered value, and a test double of such a device.
//
// A device keeps subTexelPrecisionBits (b) fraction bits of the weights within a level and
// mipmapPrecisionBits (m) of the fraction between two levels (harness::SamplerPrecision).
// Whether it truncates, rounds or snaps the coordinate first, a weight w becomes some w' in
// [0, 1] with |w' - w| <= 2^-b (truncation: < 2^-b, rounding: <= 2^-(b+1)); snapping the
// coordinate onto a grid of 2^-b texel that contains the texel centres never leaves the
// footprint, since the filtered value is continuous in it. From that (docs/preview.md
// "Sampling share"):
// - one axis:   |(t0 + w'(t1 - t0)) - (t0 + w(t1 - t0))| <= 2^-b |t1 - t0|;
// - bilinear:   f(a', b') - f(a, b) = [f(a', b') - f(a, b')] + [f(a, b') - f(a, b)], each a
//               convex combination of the two rows' (columns') differences, so
//               |df| <= 2^-b (max row difference + max column difference);
// - mip levels: (1 - l')L0' + l'L1' - (1 - l)L0 - l L1
//               = (1 - l')(L0' - L0) + l'(L1' - L1) + (l' - l)(L1 - L0), with |l' - l| <= 2^-m,
//               so |d| <= (1 - l)B0 + l B1 + 2^-m (|B1 - B0| + |L1 - L0|);
// - a cube corner, where the spec lets the device replace the missing texel by "other
//   methods" than the average of the three it has ("Cube Map Edge Handling"): taking any
//   value between the smallest and the largest of the three (the average, one of them, any
//   weighted mean) moves the result by at most the corner's weight (<= (w + 2^-b) per axis)
//   times that texel's distance to the farther of the two.
// All per channel, from the texels each fetch actually reads, so the bound is 0 where they are
// equal and small where the texture is smooth.
#pragma once
#include <array>
#include <cstdint>

#include "harness/sampler_precision.hpp"

namespace mb::preview {

using Rgb = std::array<double, 3>;

// A filtered value and, per channel, the largest change any weight quantization the limits
// allow can make to it.
struct FilteredRgb {
  Rgb value{}, bound{};
};

enum class WeightRounding { Truncate, Nearest };

// The test double of fixed-point hardware: weights within a level and the fraction between
// levels quantized to `bits`, by truncation or to nearest (which may give 1).
struct WeightQuantizer {
  harness::SamplerPrecision bits;
  WeightRounding rounding = WeightRounding::Truncate;
  double subTexel(double w) const { return quantize(w, bits.subTexelBits); }
  double mipmap(double f) const { return quantize(f, bits.mipmapBits); }
  double quantize(double w, uint32_t b) const;
};

// How a fetch filters: the limits its bound assumes (the device's) and, in tests only, a
// quantizer that filters as a fixed-point device would (null: exact weights, the reference).
struct TexelFilter {
  harness::SamplerPrecision limits;
  const WeightQuantizer* quantizer = nullptr;
};

// The 2x2 texels of a linear lookup, t[row][column], with weight `a` of column 1 and `b` of
// row 1; corner >= 0 marks t[corner / 2][corner % 2] as a cube corner texel that is the
// average of the other three.
struct Footprint {
  Rgb t[2][2]{};
  double a = 0, b = 0;
  int corner = -1;
};

FilteredRgb filterBilinear(const Footprint& f, const TexelFilter& filter);
// Linear between two levels' lookups at `fraction` of the way to `hi`.
FilteredRgb blendLevels(const FilteredRgb& lo, const FilteredRgb& hi, double fraction, const TexelFilter& filter);

}  // namespace mb::preview
