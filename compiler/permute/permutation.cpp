#include "permute/permutation.hpp"

namespace mb {

std::string Permutation::key() const {
  return material->name + "." + material->model + "." + lights + "." + environment + "." + precision;
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

}  // namespace mb
