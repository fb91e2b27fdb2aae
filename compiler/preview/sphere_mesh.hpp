// The preview's sphere: a UV sphere of radius 1 at the origin, with the vertex attributes of
// the fragment stage's reference vertex shader (shaderlib/common/engine_vertex.vert):
// position, normal, tangent with handedness, uv0.
#pragma once
#include <cstdint>

#include "harness/vulkan_graphics.hpp"

namespace mb::preview {

// Default tessellation: 128 segments around, 64 rings from pole to pole. At 512 pixels per
// sphere a segment spans ~6 pixels at the silhouette and ~12 in the middle; the interpolated
// normal deviates from the true sphere normal by at most ~(pi/128)^2/8 = 7.5e-5 rad, far
// below what shading shows (and the reference reads the interpolated normal, not the true
// one, so it is no error either way).
inline constexpr uint32_t kSphereSegments = 128;
inline constexpr uint32_t kSphereRings = 64;

// y up; longitude phi from +z towards +x, colatitude theta from +y:
//   p = n = (sin(theta) sin(phi), cos(theta), sin(theta) cos(phi)),
//   uv = (phi / 2 pi, theta / pi), tangent = dp/dphi normalized = (cos(phi), 0, -sin(phi)),
//   handedness w = -1, so that w cross(n, t) = dp/dtheta, the direction of increasing v.
// Triangles are counter-clockwise seen from outside. Vertex layout (12 floats):
// position xyz (location 0), normal xyz (1), tangent xyzw (2), uv (3).
harness::Mesh uvSphere(uint32_t segments = kSphereSegments, uint32_t rings = kSphereRings);

}  // namespace mb::preview
