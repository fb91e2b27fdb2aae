// Which permutations `validate` and `report` run for one material (docs/cli.md `validate`).
#pragma once
#include <string>
#include <vector>

#include "core/environment_mode.hpp"
#include "core/light_type.hpp"
#include "core/precision.hpp"
#include "library/shader_library.hpp"
#include "load/material_desc.hpp"
#include "permute/permutation.hpp"

namespace mb {

// The model's light types together, once per environment mode, both narrowed by `lights` /
// `environments` (empty: all), at `precision`. A mode in which the material's bricks break one
// of the model's brick rules is skipped with a note when the user did not ask for it (the
// material may be meant for other modes); asked for, it is an error when the probe is built.
std::vector<Permutation> permutationsToValidate(const MaterialDesc& m, const ShaderLibrary& lib,
                                                const std::vector<LightType>& lights,
                                                const std::vector<EnvironmentMode>& environments, Precision precision,
                                                std::vector<std::string>& notes);

}  // namespace mb
