#include "preview/texel_filter.hpp"

#include <algorithm>
#include <cmath>

namespace mb::preview {

double WeightQuantizer::quantize(double w, uint32_t b) const {
  const double scaled = std::ldexp(w, static_cast<int>(b));
  return std::ldexp(rounding == WeightRounding::Truncate ? std::floor(scaled) : std::floor(scaled + 0.5),
                    -static_cast<int>(b));
}

FilteredRgb filterBilinear(const Footprint& f, const TexelFilter& filter) {
  const double step = std::ldexp(1.0, -static_cast<int>(filter.limits.subTexelBits));
  const double a = filter.quantizer ? filter.quantizer->subTexel(f.a) : f.a;
  const double b = filter.quantizer ? filter.quantizer->subTexel(f.b) : f.b;
  // The corner's weight under any quantization: at most (w + 2^-b) per axis.
  double cornerWeight = 0;
  if (f.corner >= 0) {
    const double wa = f.corner % 2 ? f.a : 1 - f.a, wb = f.corner / 2 ? f.b : 1 - f.b;
    cornerWeight = std::min(1.0, wa + step) * std::min(1.0, wb + step);
  }
  FilteredRgb out;
  for (int c = 0; c < 3; ++c) {
    const double t00 = f.t[0][0][c], t01 = f.t[0][1][c], t10 = f.t[1][0][c], t11 = f.t[1][1][c];
    out.value[c] = (1 - a) * (1 - b) * t00 + a * (1 - b) * t01 + (1 - a) * b * t10 + a * b * t11;
    const double rows = std::max(std::abs(t01 - t00), std::abs(t11 - t10));
    const double columns = std::max(std::abs(t10 - t00), std::abs(t11 - t01));
    out.bound[c] = step * (rows + columns);
    if (f.corner >= 0) {
      double lo = INFINITY, hi = -INFINITY;
      for (int k = 0; k < 4; ++k)
        if (k != f.corner) lo = std::min(lo, f.t[k / 2][k % 2][c]), hi = std::max(hi, f.t[k / 2][k % 2][c]);
      const double corner = f.t[f.corner / 2][f.corner % 2][c];
      out.bound[c] += cornerWeight * std::max(corner - lo, hi - corner);
    }
  }
  return out;
}

FilteredRgb blendLevels(const FilteredRgb& lo, const FilteredRgb& hi, double fraction, const TexelFilter& filter) {
  const double step = std::ldexp(1.0, -static_cast<int>(filter.limits.mipmapBits));
  const double l = filter.quantizer ? filter.quantizer->mipmap(fraction) : fraction;
  FilteredRgb out;
  for (int c = 0; c < 3; ++c) {
    out.value[c] = (1 - l) * lo.value[c] + l * hi.value[c];
    out.bound[c] = (1 - fraction) * lo.bound[c] + fraction * hi.bound[c] +
                   step * (std::abs(hi.bound[c] - lo.bound[c]) + std::abs(hi.value[c] - lo.value[c]));
  }
  return out;
}

}  // namespace mb::preview
