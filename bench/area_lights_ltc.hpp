// Linearly transformed cosines (Heitz, Dupuy, Hill & Neubelt 2016) for sphere and tube lights
// against the brute-force integrals (shaderlib/common/area_light_truth.hpp), beside the
// representative-point method the standard model composes today, on the same configurations:
// perceptual roughness 0.05 to 1, n.v 0.05 to 1, sin of the light's angular radius 0.01 to 0.5,
// half of the lights near the mirror ray, the other half anywhere a part of them is above the
// horizon (partly below it included). All in double, the table read as a bilinear texture
// (ltc::sampleBilinear), the shapes as polygons (common/ltc_reference.hpp).
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "library/shader_library.hpp"
#include "ltc/ltc_table.hpp"

namespace mb::bench {

// The bricks the standard model composes a sphere light from by default (its roles'
// defaults, shaderlib/models/standard.json): the representative point LTC is set beside.
struct SphereLightBricks {
  std::string point;          // role sphere_light_point (a tube_light_point brick)
  std::string normalization;  // role sphere_energy_normalization
  std::string wrap;           // role sphere_horizon_wrap
};
SphereLightBricks standardSphereLight(const ShaderLibrary& lib);

// planarSamples: rectangles and disks (half each) drawn after the spheres and tubes.
nlohmann::json measureLtcAreaLights(const ltc::Table& table, const SphereLightBricks& representative, int sphereSamples,
                                    int tubeSamples, int planarSamples, uint64_t seed);

// The section's tables as Markdown (docs/models/lights.md).
std::string ltcMarkdown(const nlohmann::json& section);

}  // namespace mb::bench
