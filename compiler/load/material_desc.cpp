#include "load/material_desc.hpp"

#include <algorithm>

namespace mb {

bool MaterialDesc::has(const std::string& feature) const {
  return std::find(features.begin(), features.end(), feature) != features.end();
}

const MaterialParam* MaterialDesc::param(const std::string& name) const {
  for (const auto& p : params)
    if (p.name == name) return &p;
  return nullptr;
}

std::string MaterialDesc::lightMethod(LightType light) const {
  auto it = lightMethods.find(lightTypeName(light));
  return it == lightMethods.end() ? std::string() : it->second;
}

}  // namespace mb
