#include "preview/environment_cube.hpp"

#include <algorithm>
#include <cmath>

namespace mb::preview {
namespace {

Rgb texelAt(const CubeLevel& level, uint32_t face, uint32_t i, uint32_t j) {
  const size_t k = ((size_t{face} * level.size + j) * level.size + i) * 4;
  return {level.rgba[k], level.rgba[k + 1], level.rgba[k + 2]};
}

// Texel (i, j) of `face`, where at most one of i, j lies one texel outside [0, size): then
// the texel across the edge, on the adjacent face ("Cube Map Edge Handling"). It is found
// geometrically rather than from the spec's table of edge pairings: the point a tenth of a
// texel beyond the edge, at the texel's position along the edge, lies on the neighbour's
// plane within its edge texel, at that texel's position along the shared edge (the
// gnomonic scaling moves it by less than 0.1 texel).
Rgb edgeTexel(const CubeLevel& level, uint32_t face, int i, int j) {
  const int n = static_cast<int>(level.size);
  if (i >= 0 && i < n && j >= 0 && j < n) return texelAt(level, face, i, j);
  const double beyond = 0.1 / n;
  auto coord = [&](int k) { return k < 0 ? -beyond : (k >= n ? 1.0 + beyond : (k + 0.5) / n); };
  const FaceCoord fc = cubeFaceCoord(cubeFaceDirection(face, coord(i), coord(j)));
  auto index = [&](double x) {
    return static_cast<uint32_t>(std::clamp(static_cast<int>(std::floor(x * n)), 0, n - 1));
  };
  return texelAt(level, fc.face, index(fc.s), index(fc.t));
}

}  // namespace

FaceCoord cubeFaceCoord(const std::array<double, 3>& d) {
  const double ax = std::abs(d[0]), ay = std::abs(d[1]), az = std::abs(d[2]);
  FaceCoord fc;
  double sc, tc, ma;
  if (ax >= ay && ax >= az) {
    fc.face = d[0] >= 0 ? 0 : 1;
    sc = d[0] >= 0 ? -d[2] : d[2], tc = -d[1], ma = ax;
  } else if (ay >= az) {
    fc.face = d[1] >= 0 ? 2 : 3;
    sc = d[0], tc = d[1] >= 0 ? d[2] : -d[2], ma = ay;
  } else {
    fc.face = d[2] >= 0 ? 4 : 5;
    sc = d[2] >= 0 ? d[0] : -d[0], tc = -d[1], ma = az;
  }
  fc.s = 0.5 * (sc / ma + 1.0);
  fc.t = 0.5 * (tc / ma + 1.0);
  return fc;
}

std::array<double, 3> cubeFaceDirection(uint32_t face, double s, double t) {
  const double sc = 2.0 * s - 1.0, tc = 2.0 * t - 1.0;
  switch (face) {
    case 0:
      return {1.0, -tc, -sc};
    case 1:
      return {-1.0, -tc, sc};
    case 2:
      return {sc, 1.0, tc};
    case 3:
      return {sc, -1.0, -tc};
    case 4:
      return {sc, -tc, 1.0};
    default:
      return {-sc, -tc, -1.0};
  }
}

std::array<double, 3> cubeTexelDirection(uint32_t face, uint32_t i, uint32_t j, uint32_t size) {
  std::array<double, 3> d = cubeFaceDirection(face, (i + 0.5) / size, (j + 0.5) / size);
  const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return {d[0] / len, d[1] / len, d[2] / len};
}

double cubeTexelSolidAngle(uint32_t i, uint32_t j, uint32_t size) {
  auto area = [](double x, double y) { return std::atan2(x * y, std::sqrt(x * x + y * y + 1.0)); };
  const double x0 = 2.0 * i / size - 1.0, x1 = 2.0 * (i + 1) / size - 1.0;
  const double y0 = 2.0 * j / size - 1.0, y1 = 2.0 * (j + 1) / size - 1.0;
  return area(x0, y0) - area(x0, y1) - area(x1, y0) + area(x1, y1);
}

FilteredRgb sampleCubeLevel(const CubeLevel& level, const FaceCoord& fc, const TexelFilter& filter) {
  const double u = fc.s * level.size - 0.5, v = fc.t * level.size - 0.5;
  const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
  Footprint f;
  f.a = u - i0, f.b = v - j0;
  const int n = static_cast<int>(level.size);
  auto outside = [n](int k) { return k < 0 || k >= n; };
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      if (outside(i0 + dx) && outside(j0 + dy))
        f.corner = dy * 2 + dx;
      else
        f.t[dy][dx] = edgeTexel(level, fc.face, i0 + dx, j0 + dy);
    }
  // At a cube corner three faces meet and the fourth texel of the footprint does not exist;
  // it is taken as the average of the other three (the spec's suggested behaviour, and
  // lavapipe's; texel_filter.hpp bounds what other methods may give).
  if (f.corner >= 0) {
    Rgb& c = f.t[f.corner / 2][f.corner % 2];
    c = {0, 0, 0};
    for (int k = 0; k < 4; ++k)
      if (k != f.corner)
        for (int ch = 0; ch < 3; ++ch) c[ch] += f.t[k / 2][k % 2][ch] / 3.0;
  }
  return filterBilinear(f, filter);
}

FilteredRgb EnvironmentMaps::sampleFiltered(const std::array<double, 3>& dir, double lod,
                                            const TexelFilter& filter) const {
  if (levels.empty()) return {};
  const FaceCoord fc = cubeFaceCoord(dir);
  const double q = maxMip();
  const double d = std::clamp(lod, 0.0, q);
  const auto lo = static_cast<size_t>(std::floor(d));
  const double frac = d - lo;
  const FilteredRgb low = sampleCubeLevel(levels[lo], fc, filter);
  // An exact integer level (or the clamped ends) has fraction 0, which every quantization keeps.
  if (!(frac > 0.0 && lo + 1 < levels.size())) return low;
  return blendLevels(low, sampleCubeLevel(levels[lo + 1], fc, filter), frac, filter);
}

std::array<double, 3> EnvironmentMaps::sample(const std::array<double, 3>& dir, double lod) const {
  return sampleFiltered(dir, lod, TexelFilter{}).value;
}

}  // namespace mb::preview
