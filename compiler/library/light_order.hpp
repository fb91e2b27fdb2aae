// The one order light types are listed in (allLightTypes(), library/shader_library.hpp): a
// scene's lights (load/), a permutation's and its key (permute/) all use it.
#pragma once
#include <string>
#include <vector>

namespace mb {

// Sorts light types into allLightTypes() order and drops duplicates.
std::vector<std::string> canonicalLights(std::vector<std::string> lights);

}  // namespace mb
