// A permutation: one specialized shader of one material, for one set of light types, one
// environment mode and one precision (docs/models.md "Permutation axes"). The key names every
// axis, so that later axes extend it without renaming existing outputs.
#pragma once
#include <string>
#include <vector>

#include "load/material_desc.hpp"

namespace mb {

struct Permutation {
  const MaterialDesc* material = nullptr;
  std::vector<std::string> lights{"dir"};  // light types, in allLightTypes() order
  std::string environment = "none";        // one of allEnvironmentModes()
  std::string precision = "fp32";
  // Stable, readable and file-name safe: "<material>.<model>.<lights>.<env>.<precision>",
  // lights joined by '+' ("dir+point+sphere").
  std::string key() const;
  std::string lightsKey() const;
  bool hasLight(const std::string& type) const;
};

// The permutations a list of materials needs by default: a directional light, no
// environment, fp32 (what eval, stress and bench run), in input order.
std::vector<Permutation> permutationsFor(const std::vector<MaterialDesc>& materials);

// What `validate` runs for one material: every light type its model shades together, once
// per environment mode the model supports.
std::vector<Permutation> validationPermutationsFor(const MaterialDesc& material, const ShaderLibrary& lib);

// Sorts light types into allLightTypes() order and drops duplicates.
std::vector<std::string> canonicalLights(std::vector<std::string> lights);

}  // namespace mb
