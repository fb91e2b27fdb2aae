// The preview environments' radiance as a function of direction (docs/environments.md),
// in double here and in GLSL in shaderlib/environments/<name>.glsl (what the prefilter
// kernels evaluate). The parameters live only here: radianceGlsl writes them into the kernel
// as constants, so the two implementations cannot disagree on a number, only on a formula,
// which the tests compare (level 0 of a built cube against radiance()).
//
// Conventions: world space, +y up; azimuth measured from +z towards +x; radiance in
// scene-linear relative units (1 ~ a bright overcast sky).
#pragma once
#include <array>
#include <string>
#include <vector>

namespace mb {
class GlslWriter;
class ShaderLibrary;
}

namespace mb::preview {

using Dir = std::array<double, 3>;
using Rgb = std::array<double, 3>;

// A rectangular area emitter seen from the centre of the studio: its centre direction at
// (azimuth, elevation), axes u (horizontal) and v = c x u, and a half-extent per axis in the
// gnomonic coordinates of the plane tangent at c (x = d.u / d.c, y = d.v / d.c). Its edges
// fall off smoothly over +-softness (smoothstep), so no feature is sharper than a few texels
// of a 128 cube.
struct SoftBox {
  double azimuthDeg, elevationDeg;
  double halfWidth, halfHeight;
  Rgb radiance;
};

struct StudioParams {
  std::vector<SoftBox> boxes;
  double softness;      // edge half-width, gnomonic units
  Rgb wall;             // dark backdrop at the horizon
  Rgb wallTop;          // backdrop towards the zenith
  Rgb ground;           // dim floor below the horizon
  double horizonBlend;  // floor-to-wall blend over y in [-horizonBlend, 0]
};

struct SkyParams {
  double sunAzimuthDeg, sunElevationDeg;
  double sunRadius;      // angular radius of the disc, radians
  double sunEdge;        // half-width of the disc's soft edge, radians
  double limbDarkening;  // linear law I(mu) = 1 - u (1 - mu) (Eddington-like)
  Rgb sun;               // radiance at the disc centre
  Rgb zenith, horizon;   // gradient: horizon + (zenith - horizon)(1 - (1 - y)^4)
  Rgb glow;              // forward-scattering halo: glow exp((cos(gamma) - 1) / glowWidth)
  double glowWidth;
  Rgb ground;
  double horizonBlend;
};

const StudioParams& studioParams();
const SkyParams& skyParams();

// The radiance towards unit direction d. Throws std::out_of_range for an unknown name.
Rgb environmentRadiance(const std::string& name, const Dir& d);

// A small, very bright part of an environment (the sky's sun) that the prefilter integrates
// by sampling its cone instead of the GGX lobe: zero outside the cone of axis `axis` and
// 1 - cos(half-angle) = oneMinusCosMax; u, v complete the axis to an orthonormal frame.
struct PeakCone {
  Dir axis, u, v;
  double oneMinusCosMax = 0;
};
// The cone of the named environment's peak, or nullptr when it has none (the studio).
const PeakCone* environmentPeak(const std::string& name);
// The peak's radiance (zero outside its cone) and the rest; their sum is environmentRadiance.
Rgb environmentPeakRadiance(const std::string& name, const Dir& d);
Rgb environmentSmoothRadiance(const std::string& name, const Dir& d);

// Writes GLSL defining `vec3 mb_environment_radiance(vec3 d)`, `mb_environment_smooth(d)` and,
// where environmentPeak is not null, `mb_environment_sun(d)` (the peak) with the constants
// kPeakAxis, kPeakU, kPeakV, kPeakOneMinusCosMax, for the named environment: its
// parameters as constants, then shaderlib/environments/<name>.glsl behind a #line directive.
void writeRadianceGlsl(GlslWriter& w, const ShaderLibrary& lib, const std::string& name);

}  // namespace mb::preview
