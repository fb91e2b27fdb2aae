// Unit directions for the area-light benches' random configurations (bench_area_lights.cpp,
// area_lights_ltc.cpp).
#pragma once
#include <algorithm>
#include <cmath>

#include "common/lights_reference.hpp"

namespace mb::bench {

// The unit vector at polar cosine cosTheta about z and azimuth phi.
inline ref::Vec3 unitFromAngles(double cosTheta, double phi) {
  double s = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return {s * std::cos(phi), s * std::sin(phi), cosTheta};
}

// A unit vector at angle `angle` from the unit vector a, in azimuth phi.
inline ref::Vec3 around(const ref::Vec3& a, double angle, double phi) {
  return ref::lights::onCone(a, ref::lights::frameAround(a), std::cos(angle), std::sin(angle), phi);
}

}  // namespace mb::bench
