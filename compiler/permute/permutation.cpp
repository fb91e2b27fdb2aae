#include "permute/permutation.hpp"

#include <algorithm>

namespace mb {

std::string Permutation::lightsKey() const {
  std::string s;
  for (LightType t : lights) s += (s.empty() ? "" : "+") + lightTypeName(t);
  return s.empty() ? "nolights" : s;
}

bool Permutation::hasLight(LightType type) const {
  return std::find(lights.begin(), lights.end(), type) != lights.end();
}

bool lightReadsLtcTable(const MaterialDesc& material, LightType light) {
  return isLtcLight(light) || material.lightMethod(light) == kLtcLightMethod;
}

bool Permutation::readsLtcTable() const {
  return std::any_of(lights.begin(), lights.end(), [&](LightType t) { return lightReadsLtcTable(*material, t); });
}

bool Permutation::readsSheenLtcTable() const { return readsLtcTable() && material->has("sheen"); }

std::string Permutation::key() const {
  std::string k = material->name + "." + material->model + "." + lightsKey() + "." + environmentModeName(environment) +
                  "." + precisionName(precision);
  if (quality != Quality::High) k += "." + qualityName(quality);
  for (const auto& f : folded) k += ".without-" + f;
  return k;
}

std::vector<Permutation> permutationsFor(const std::vector<MaterialDesc>& materials) {
  std::vector<Permutation> out;
  out.reserve(materials.size());
  for (const auto& m : materials) {
    Permutation p;
    p.material = &m;
    out.push_back(p);
  }
  return out;
}

std::vector<Permutation> validationPermutationsFor(const MaterialDesc& material, const ShaderLibrary& lib) {
  std::vector<Permutation> out;
  const ShadingModel* model = lib.findModel(material.model);
  if (!model) return out;
  for (EnvironmentMode env : model->environments) {
    Permutation p;
    p.material = &material;
    p.lights = canonicalLights(model->lights);
    p.environment = env;
    out.push_back(p);
  }
  return out;
}

}  // namespace mb
