#include "driver/validation_plan.hpp"

#include <algorithm>

#include "permute/axes.hpp"

namespace mb {

std::vector<Permutation> permutationsToValidate(const MaterialDesc& m, const ShaderLibrary& lib,
                                                const std::vector<LightType>& lights,
                                                const std::vector<EnvironmentMode>& environments, Precision precision,
                                                std::vector<std::string>& notes) {
  std::vector<Permutation> out;
  for (auto perm : validationPermutationsFor(m, lib)) {
    if (!environments.empty() &&
        std::find(environments.begin(), environments.end(), perm.environment) == environments.end())
      continue;
    if (!lights.empty()) perm.lights = canonicalLights(lights);
    perm.precision = precision;
    if (environments.empty())
      if (auto broken = brokenBrickRule(*lib.findModel(m.model), perm)) {
        notes.push_back("skipping environment '" + environmentModeName(perm.environment) + "': " + broken->message);
        continue;
      }
    out.push_back(perm);
  }
  return out;
}

}  // namespace mb
