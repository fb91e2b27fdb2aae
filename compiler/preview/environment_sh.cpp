#include "preview/environment_sh.hpp"

#include <cmath>

#include "preview/environment_cube.hpp"

namespace mb::preview {

std::array<double, 9> sh9Basis(const std::array<double, 3>& d) {
  constexpr double kPi = 3.14159265358979323846;
  const double x = d[0], y = d[1], z = d[2];
  const double y00 = 0.5 * std::sqrt(1.0 / kPi);
  const double y1 = std::sqrt(3.0 / (4.0 * kPi));
  const double y2a = 0.5 * std::sqrt(15.0 / kPi);
  const double y20 = 0.25 * std::sqrt(5.0 / kPi);
  const double y22 = 0.25 * std::sqrt(15.0 / kPi);
  return {y00,
          y1 * y,
          y1 * z,
          y1 * x,
          y2a * x * y,
          y2a * y * z,
          y20 * (3.0 * z * z - 1.0),
          y2a * x * z,
          y22 * (x * x - y * y)};
}

void projectSh9(const CubeLevel& level, double out[9][3]) {
  for (int k = 0; k < 9; ++k) out[k][0] = out[k][1] = out[k][2] = 0.0;
  const uint32_t n = level.size;
  for (uint32_t f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < n; ++j)
      for (uint32_t i = 0; i < n; ++i) {
        const std::array<double, 9> y = sh9Basis(cubeTexelDirection(f, i, j, n));
        const double omega = cubeTexelSolidAngle(i, j, n);
        const float* texel = &level.rgba[((size_t{f} * n + j) * n + i) * 4];
        for (int k = 0; k < 9; ++k)
          for (int c = 0; c < 3; ++c) out[k][c] += texel[c] * y[k] * omega;
      }
}

}  // namespace mb::preview
