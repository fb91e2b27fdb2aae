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

}  // namespace mb
