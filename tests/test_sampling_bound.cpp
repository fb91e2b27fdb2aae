// The sampling bound of a texture fetch (compiler/preview/texel_filter.hpp, docs/preview.md
// "Sampling share"): every weight and LOD-fraction quantization that 4 or 8 bits of
// subTexelPrecisionBits / mipmapPrecisionBits allow, and every corner replacement between the
// three texels a cube corner has, stays within it; it is 0 on equal texels and follows the
// texel differences on a smooth cube.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "preview/environment.hpp"
#include "preview/environment_cube.hpp"
#include "preview/texel_filter.hpp"

using namespace mb;
using namespace mb::preview;

namespace {

// Every weight w' on the 2^-bits grid within 2^-bits of w, clamped to [0, 1]: what truncation,
// rounding to nearest or snapping the coordinate can give.
std::vector<double> allowedWeights(double w, uint32_t bits) {
  const double step = std::ldexp(1.0, -static_cast<int>(bits));
  std::vector<double> out;
  for (double k = std::floor(w / step) - 1; k <= std::ceil(w / step) + 1; ++k) {
    const double q = k * step;
    if (q >= 0 && q <= 1 && std::abs(q - w) <= step) out.push_back(q);
  }
  return out;
}

double bilinear(const Footprint& f, double a, double b, int c) {
  return (1 - a) * (1 - b) * f.t[0][0][c] + a * (1 - b) * f.t[0][1][c] + (1 - a) * b * f.t[1][0][c] +
         a * b * f.t[1][1][c];
}

// Texels spread over several orders of magnitude (a sun texel beside sky texels) or close
// together (a smooth region), as the environments have them.
Footprint randomFootprint(std::mt19937_64& rng, bool corner) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Footprint f;
  const double scale = std::pow(10.0, 4.0 * u(rng) - 1.0);
  for (auto& row : f.t)
    for (auto& texel : row)
      for (double& c : texel) c = u(rng) < 0.2 ? scale * u(rng) : 1.0 + 0.01 * u(rng);
  f.a = u(rng), f.b = u(rng);
  if (corner) {
    f.corner = static_cast<int>(rng() % 4);
    Rgb& t = f.t[f.corner / 2][f.corner % 2];
    t = {0, 0, 0};
    for (int k = 0; k < 4; ++k)
      if (k != f.corner)
        for (int c = 0; c < 3; ++c) t[c] += f.t[k / 2][k % 2][c] / 3.0;
  }
  return f;
}

}  // namespace

TEST_CASE("the bilinear sampling bound covers every weight quantization the precision allows", "[sampling]") {
  std::mt19937_64 rng(20240601);
  for (const uint32_t bits : {4u, 8u}) {
    const TexelFilter filter{{bits, bits}, nullptr};
    double tightest = 0;  // the largest change found over the bound
    for (int trial = 0; trial < 3000; ++trial) {
      const bool corner = trial % 3 == 0;
      const Footprint f = randomFootprint(rng, corner);
      const FilteredRgb exact = filterBilinear(f, filter);
      // A corner texel may be replaced by any value between the three the device has.
      std::vector<Footprint> replaced{f};
      if (corner)
        for (int k = 0; k < 4; ++k)
          if (k != f.corner) {
            Footprint g = f;
            g.t[f.corner / 2][f.corner % 2] = f.t[k / 2][k % 2];
            replaced.push_back(g);
          }
      for (const Footprint& g : replaced)
        for (double a : allowedWeights(f.a, bits))
          for (double b : allowedWeights(f.b, bits))
            for (int c = 0; c < 3; ++c) {
              const double change = std::abs(bilinear(g, a, b, c) - exact.value[c]);
              INFO("bits " << bits << " trial " << trial << " channel " << c);
              REQUIRE(change <= exact.bound[c] * (1 + 1e-12) + 1e-300);
              if (exact.bound[c] > 0) tightest = std::max(tightest, change / exact.bound[c]);
            }
    }
    // Tight: some quantization comes within 20% of it (the bound is a sum of worst cases
    // that one weight pair can nearly attain together).
    CHECK(tightest > 0.8);
  }
}

TEST_CASE("the test double quantizes as fixed-point hardware may", "[sampling]") {
  const WeightQuantizer truncate{{4, 8}, WeightRounding::Truncate}, nearest{{4, 8}, WeightRounding::Nearest};
  CHECK(truncate.subTexel(0.99) == 0.9375);
  CHECK(nearest.subTexel(0.99) == 1.0);
  CHECK(truncate.subTexel(0.03) == 0.0);
  CHECK(nearest.subTexel(0.04) == 0.0625);
  CHECK(truncate.mipmap(0.5 + 1.0 / 1024) == 0.5);
  CHECK(nearest.mipmap(1.0 / 1024) == 0.0);
  // Integers stay put: the exact levels and texel centres every device hits.
  CHECK(nearest.mipmap(0.0) == 0.0);
  CHECK(truncate.subTexel(0.5) == 0.5);
}

TEST_CASE("the mip blend's bound covers every LOD-fraction quantization", "[sampling]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const uint32_t bits : {4u, 8u}) {
    const TexelFilter filter{{bits, bits}, nullptr};
    for (int trial = 0; trial < 2000; ++trial) {
      const Footprint f0 = randomFootprint(rng, false), f1 = randomFootprint(rng, trial % 2 == 0);
      const double fraction = u(rng);
      const FilteredRgb lo = filterBilinear(f0, filter), hi = filterBilinear(f1, filter);
      const FilteredRgb exact = blendLevels(lo, hi, fraction, filter);
      for (double l : allowedWeights(fraction, bits))
        for (double a0 : allowedWeights(f0.a, bits))
          for (double a1 : allowedWeights(f1.a, bits))
            for (int c = 0; c < 3; ++c) {
              // The worst b of each level: its bound's other axis at the grid's ends.
              for (double b0 : {allowedWeights(f0.b, bits).front(), allowedWeights(f0.b, bits).back()})
                for (double b1 : {allowedWeights(f1.b, bits).front(), allowedWeights(f1.b, bits).back()}) {
                  const double got = (1 - l) * bilinear(f0, a0, b0, c) + l * bilinear(f1, a1, b1, c);
                  INFO("bits " << bits << " trial " << trial);
                  REQUIRE(std::abs(got - exact.value[c]) <= exact.bound[c] * (1 + 1e-12));
                }
            }
    }
  }
}

TEST_CASE("a cube fetch's bound is 0 on a constant cube and follows the texels on a smooth one", "[sampling]") {
  // Level texels from a function of direction; 32, 16, ..., 1 per face like the test
  // environments.
  auto cube = [](auto radiance) {
    EnvironmentMaps env;
    for (uint32_t size = 32; size >= 1; size /= 2) {
      CubeLevel level{size, std::vector<float>(size_t{6} * size * size * 4)};
      for (uint32_t f = 0; f < 6; ++f)
        for (uint32_t j = 0; j < size; ++j)
          for (uint32_t i = 0; i < size; ++i) {
            const auto d = cubeTexelDirection(f, i, j, size);
            float* t = &level.rgba[((size_t{f} * size + j) * size + i) * 4];
            for (int c = 0; c < 3; ++c) t[c] = static_cast<float>(radiance(d, c));
            t[3] = 1;
          }
      env.levels.push_back(std::move(level));
    }
    return env;
  };
  const EnvironmentMaps flat = cube([](const std::array<double, 3>&, int c) { return 2.0 + c; });
  // Smooth: 1 + 0.5 z changes by at most 0.5 per radian, and neighbouring texel centres of a
  // 32 face are at most 2/32 rad apart (the face centre's spacing, where the gnomonic grid is
  // widest in angle), so each axis' difference is <= 1/32 at level 0.
  const EnvironmentMaps smooth = cube([](const std::array<double, 3>& d, int) { return 1.0 + 0.5 * d[2]; });
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0.0, 5.0);
  const TexelFilter eight{{8, 8}, nullptr};
  double worstLevel0 = 0;
  for (int k = 0; k < 4000; ++k) {
    const std::array<double, 3> dir{g(rng), g(rng), g(rng)};
    const double lod = k % 2 ? 0.0 : u(rng);
    const FilteredRgb f = flat.sampleFiltered(dir, lod, eight);
    for (int c = 0; c < 3; ++c) {
      // 0 within a level; the mip blend adds 2^-m times the double rounding of the two levels'
      // values.
      CHECK(f.bound[c] <= 1e-15 * (2.0 + c));
      CHECK(std::abs(f.value[c] - (2.0 + c)) < 1e-6);
    }
    // Away from the corners (where the spec leaves the missing texel's method open), level 0
    // fetches stay within 2^-8 (rows + columns) <= 2^-8 * 2/32.
    const FaceCoord fc = cubeFaceCoord(dir);
    const bool nearCorner = std::min(fc.s, 1 - fc.s) < 1.0 / 32 && std::min(fc.t, 1 - fc.t) < 1.0 / 32;
    if (lod == 0.0 && !nearCorner) worstLevel0 = std::max(worstLevel0, smooth.sampleFiltered(dir, 0.0, eight).bound[0]);
  }
  CHECK(worstLevel0 > 0);
  CHECK(worstLevel0 <= std::ldexp(1.0, -8) * 2.0 / 32);
}
