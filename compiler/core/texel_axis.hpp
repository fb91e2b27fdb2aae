// core: one axis of a clamp-to-edge bilinear lookup with texel centres at (i + 0.5) / n, the
// convention of the DFG LUT (DESIGN.md) and of a Vulkan sampler with CLAMP_TO_EDGE.
#pragma once
#include <algorithm>
#include <cmath>

namespace mb {

struct TexelAxis {
  int i0 = 0, i1 = 0;  // the two texels, clamped to [0, n - 1]
  double w = 0;        // the weight of i1
};

inline TexelAxis texelAxis(double coord, int n) {
  const double t = coord * n - 0.5, f = std::floor(t);
  return {std::clamp(static_cast<int>(f), 0, n - 1), std::clamp(static_cast<int>(f) + 1, 0, n - 1), t - f};
}

}  // namespace mb
