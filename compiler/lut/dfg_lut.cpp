#include "lut/dfg_lut.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/ibl_reference.hpp"
#include "core/parallel.hpp"
#include "core/texel_axis.hpp"

namespace mb::lut {

std::vector<float> texelInputs(uint32_t size) {
  std::vector<float> in;
  in.reserve(static_cast<size_t>(size) * size * 2);
  for (uint32_t j = 0; j < size; ++j) {
    for (uint32_t i = 0; i < size; ++i) {
      in.push_back(static_cast<float>(texelCentre(i, size)));
      in.push_back(static_cast<float>(texelCentre(j, size)));
    }
  }
  return in;
}

std::string lutFormatName(LutFormat f) { return f == LutFormat::Fp16 ? "fp16" : "fp32"; }

DfgLut buildDfgLut(uint32_t size) {
  DfgLut lut;
  lut.size = size;
  lut.x.resize(size_t{size} * size);
  lut.y.resize(size_t{size} * size);
  parallelFor(size_t{size} * size, [&](size_t t) {
    double NoV = (t % size + 0.5) / size, perceptualRoughness = (t / size + 0.5) / size;
    ref::DfgIntegrals d = ref::dfgIntegrals(NoV, perceptualRoughness * perceptualRoughness);
    lut.x[t] = d.gvFc;
    lut.y[t] = d.gv;
  });
  return lut;
}

double roundToHalf(double value) {
  if (!std::isfinite(value) || value == 0.0) return value;
  double mag = std::abs(value);
  // Spacing of binary16 values: 2^-24 below the smallest normal 2^-14, else 2^(e - 10).
  int e = std::ilogb(mag);
  double step = e < -14 ? std::ldexp(1.0, -24) : std::ldexp(1.0, e - 10);
  double rounded = std::nearbyint(mag / step) * step;  // default rounding: nearest even
  if (rounded > 65504.0) rounded = std::numeric_limits<double>::infinity();
  return std::copysign(rounded, value);
}

DfgLut quantize(const DfgLut& lut, LutFormat format) {
  DfgLut q = lut;
  auto round = [format](double v) {
    return format == LutFormat::Fp16 ? roundToHalf(v) : double(static_cast<float>(v));
  };
  std::transform(q.x.begin(), q.x.end(), q.x.begin(), round);
  std::transform(q.y.begin(), q.y.end(), q.y.begin(), round);
  return q;
}

DfgSample sampleBilinear(const DfgLut& lut, double u, double v) {
  const int n = static_cast<int>(lut.size);
  const TexelAxis x = texelAxis(u, n), y = texelAxis(v, n);
  const int i0 = x.i0, i1 = x.i1, j0 = y.i0, j1 = y.i1;
  const double fu = x.w, fv = y.w;
  auto lerp2 = [&](const std::vector<double>& c) {
    auto at = [&](int i, int j) { return c[size_t(j) * n + i]; };
    double lo = at(i0, j0) + (at(i1, j0) - at(i0, j0)) * fu;
    double hi = at(i0, j1) + (at(i1, j1) - at(i0, j1)) * fu;
    return lo + (hi - lo) * fv;
  };
  return {lerp2(lut.x), lerp2(lut.y)};
}

}  // namespace mb::lut
