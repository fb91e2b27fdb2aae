// Reference for wrap_green: Green 2004 (GPU Gems ch. 16), diffuse = max(0, (L.N + wrap) / (1 + wrap)).
#include <algorithm>

#include "common/reference.hpp"

namespace mb::ref {

static Vec3 wrapGreen(Geometry g, double wrap, Vec3) {
  return splat(std::max(0.0, (dot(g.l, g.n) + wrap) / (1.0 + wrap)));
}

MB_REFERENCE("wrap_green", wrapGreen);

}  // namespace mb::ref
