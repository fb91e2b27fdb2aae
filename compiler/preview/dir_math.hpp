// The few vector operations the preview's double-precision environment code needs on
// std::array<double, 3> (directions and colours), in one place for every file of preview/.
#pragma once
#include <array>
#include <cmath>

namespace mb::preview {

inline double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline std::array<double, 3> normalized(const std::array<double, 3>& v) {
  const double l = std::sqrt(dot(v, v));
  return {v[0] / l, v[1] / l, v[2] / l};
}

}  // namespace mb::preview
