// Cube-map geometry in double, as Vulkan defines it (Vulkan spec, "Cube Map Face Selection"
// and "Cube Map Edge Handling"): the face and (s, t) of a direction, the direction of a
// texel, a texel's exact solid angle, and the filtered lookup that EnvironmentMaps::sample
// performs.
#pragma once
#include <array>
#include <cstdint>

#include "preview/environment.hpp"
#include "preview/texel_filter.hpp"

namespace mb::preview {

struct FaceCoord {
  uint32_t face = 0;  // Vulkan layer: +X, -X, +Y, -Y, +Z, -Z
  double s = 0, t = 0;
};

// The spec's table: the major axis picks the face (ties go to x, then y, as lavapipe and
// most hardware break them), then s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2.
FaceCoord cubeFaceCoord(const std::array<double, 3>& dir);
// The (unnormalized) direction at (s, t) of a face: the inverse of the table, also valid for
// s, t outside [0, 1] (a point on the face's plane beyond its edge).
std::array<double, 3> cubeFaceDirection(uint32_t face, double s, double t);
// Unit direction of texel (i, j)'s centre on a size x size face.
std::array<double, 3> cubeTexelDirection(uint32_t face, uint32_t i, uint32_t j, uint32_t size);
// Exact solid angle of texel (i, j): the area of its square on the unit-distance face plane
// projected onto the sphere, from the closed form Int dx dy / (1 + x^2 + y^2)^(3/2) =
// atan(x y / sqrt(1 + x^2 + y^2)) evaluated at the four corners.
double cubeTexelSolidAngle(uint32_t i, uint32_t j, uint32_t size);

// Bilinear lookup of one level at (face, s, t) with seamless edges, with its sampling bound.
FilteredRgb sampleCubeLevel(const CubeLevel& level, const FaceCoord& fc, const TexelFilter& filter);

}  // namespace mb::preview
