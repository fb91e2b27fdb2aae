// The validation probe's scene (docs/models.md "Validation probe"): which record inputs
// describe the shading frame, one light of each type present and the environment, and the
// GLSL that builds them. compiler/validate/probe_scene_reference.cpp mirrors the construction in double
// for the reference; both read the same fp32 record.
#pragma once
#include <string>
#include <vector>

#include "core/environment_mode.hpp"
#include "library/shader_library.hpp"

namespace mb {

struct ProbeSceneInput {
  std::string name;
  ValueType type = ValueType::Float;
  Range range;
};

struct ProbeScene {
  std::vector<LightType> lights;  // light types present
  EnvironmentMode environment = EnvironmentMode::None;
  bool illuminanceInput = false;  // directional light's illuminance from the record
  // Geometric-normal tilt and tangent angle as inputs (else ng = n and t = basis tangent):
  // every permutation except the vertical slice's single directional light without features.
  bool fullFrame = false;
  // Rectangle and disk lights look the LTC table up in the harness's table buffer, as the
  // fragment stage looks up its texture (the validation probe: emit/ltc_table_lookup.hpp);
  // otherwise every lookup returns the record's one texel (an engine kernel's records).
  bool ltcTableBuffer = false;
  // The lights read the LTC table (Permutation::readsLtcTable: rectangles and disks, and
  // spheres and tubes by the "ltc" method).
  bool ltcTable = false;
  // ...and the material has a sheen, whose lobe reads the sheen's table.
  bool ltcSheen = false;
  bool has(LightType light) const;
  bool recordLtcTexel() const;  // the lights read the LTC table, from the record
};

// Inputs after n, v, l, in record order.
std::vector<ProbeSceneInput> probeSceneInputs(const ProbeScene& scene);
// Largest illuminance (or environment radiance) the scene's inputs can produce, summed over
// its lights: absolute tolerances of a unit-illuminance composition scale with it.
double probeSceneRadianceBound(const ProbeScene& scene);
// GLSL (fp32 text) defining the fetch hooks and mb_probe_environment_shape, placed before main;
// with ltcTableBuffer the LTC hooks are ltcTableLookup's, which the emitter writes itself.
std::vector<std::string> probeSceneGlobals(const ProbeScene& scene);
// GLSL statements of main() that build `ShadingFrame f` from p_n, p_v and the inputs, and
// set the fetch hooks' values.
std::vector<std::string> probeSceneFrame(const ProbeScene& scene);
// GLSL statements that add every light and the environment to `vec3 r`, given `px` and `f`.
std::vector<std::string> probeSceneShading(const ProbeScene& scene);

// The mip level of the roughest prefiltered level in the probe's environment.
inline constexpr double kProbeMaxMip = 8.0;

}  // namespace mb
