// A permutation: one specialized shader of one material. The vertical slice has one axis
// value each (directional light, no environment, fp32); the key names every axis so that
// later axes extend it without renaming existing outputs.
#pragma once
#include <string>
#include <vector>

#include "load/material_desc.hpp"

namespace mb {

struct Permutation {
  const MaterialDesc* material = nullptr;
  std::string lights = "dir";    // set of light types
  std::string environment = "none";
  std::string precision = "fp32";
  // Stable, readable and file-name safe: "<material>.<model>.<lights>.<env>.<precision>".
  std::string key() const;
};

// The permutations a list of materials needs (one each for now), in input order.
std::vector<Permutation> permutationsFor(const std::vector<MaterialDesc>& materials);

}  // namespace mb
