#include "preview/sphere_mesh.hpp"

#include <cmath>
#include <numbers>

namespace mb::preview {

harness::Mesh uvSphere(uint32_t segments, uint32_t rings) {
  harness::Mesh m;
  m.floatsPerVertex = 12;
  m.attributes = {{0, 3, 0}, {1, 3, 3}, {2, 4, 6}, {3, 2, 10}};
  const double pi = std::numbers::pi;
  // (segments + 1) columns: the seam repeats its vertices with u = 0 and u = 1.
  for (uint32_t r = 0; r <= rings; ++r) {
    const double theta = pi * r / rings;
    for (uint32_t s = 0; s <= segments; ++s) {
      const double phi = 2.0 * pi * s / segments;
      const float p[3] = {static_cast<float>(std::sin(theta) * std::sin(phi)), static_cast<float>(std::cos(theta)),
                          static_cast<float>(std::sin(theta) * std::cos(phi))};
      const float t[3] = {static_cast<float>(std::cos(phi)), 0.0f, static_cast<float>(-std::sin(phi))};
      m.vertices.insert(m.vertices.end(), {p[0], p[1], p[2], p[0], p[1], p[2], t[0], t[1], t[2], -1.0f,
                                           static_cast<float>(static_cast<double>(s) / segments),
                                           static_cast<float>(static_cast<double>(r) / rings)});
    }
  }
  // Quad (r, s): a = (r, s), b = (r, s + 1), c = (r + 1, s), d = (r + 1, s + 1). Seen from
  // outside, with +y up, s increases to the right (towards +x at phi = 0) and r downwards, so
  // a-c-b and b-c-d run counter-clockwise. The pole rows' degenerate triangles are skipped.
  const uint32_t columns = segments + 1;
  for (uint32_t r = 0; r < rings; ++r) {
    for (uint32_t s = 0; s < segments; ++s) {
      const uint32_t a = r * columns + s, b = a + 1, c = a + columns, d = c + 1;
      if (r != 0) m.indices.insert(m.indices.end(), {a, c, b});
      if (r + 1 != rings) m.indices.insert(m.indices.end(), {b, c, d});
    }
  }
  return m;
}

}  // namespace mb::preview
