// The environment axis of a permutation (docs/models.md "Permutation axes"), as a type and one
// table of names. The name is parsed once where it enters (the command line, a scene, a
// shard, a model's manifest); a Permutation holds the value, and its name appears only in
// keys, file names, JSON and the MB_ENV_<NAME> define. Which modes a model shades is the
// library's data (its manifest's "environments"); the modes themselves are the compiler's,
// since the emitter and the probe scenes give each its bindings.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mb {

// In axis order: the order the command line, a scene's "expected one of" and a scene's
// environments list them.
enum class EnvironmentMode { None, Sh, IblLut, IblAnalytic };

const std::string& environmentModeName(EnvironmentMode e);  // "none", "sh", "ibl_lut", "ibl_analytic"
// Every mode, in axis order.
const std::vector<EnvironmentMode>& allEnvironmentModes();
// Their names, in the same order (what the command line, a scene and a manifest accept).
const std::vector<std::string>& allEnvironmentModeNames();
// nullopt for a name that is not a mode.
std::optional<EnvironmentMode> parseEnvironmentMode(std::string_view name);
// Names already checked against allEnvironmentModeNames(); throws std::invalid_argument for any
// other name.
std::vector<EnvironmentMode> parseEnvironmentModes(const std::vector<std::string>& names);
// The names of `modes`, in their order (messages, JSON).
std::vector<std::string> environmentModeNames(const std::vector<EnvironmentMode>& modes);

// Image-based: a prefiltered radiance cube (samplerCube binding, MB_ENV_IBL).
bool isIbl(EnvironmentMode e);
// The split-sum DFG term read from the LUT texture (ibl_lut), not the analytic fit (ibl_analytic).
bool usesDfgLut(EnvironmentMode e);

}  // namespace mb
