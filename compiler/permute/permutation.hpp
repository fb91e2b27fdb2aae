// A permutation: one specialized shader of one material, for one set of light types, one
// environment mode and one precision (docs/models.md "Permutation axes"). The key names every
// axis, so that later axes extend it without renaming existing outputs.
#pragma once
#include <string>
#include <vector>

#include "core/environment_mode.hpp"
#include "core/precision.hpp"
#include "core/quality.hpp"
#include "core/light_type.hpp"  // canonicalLights(): the order of `lights`
#include "load/material_desc.hpp"

namespace mb {

struct Permutation {
  // The material as this permutation shades it: after quality selection and feature folding
  // (permute/specialize.hpp), `material` is the specialized copy, not the loaded one.
  const MaterialDesc* material = nullptr;
  std::vector<LightType> lights{LightType::Dir};  // in canonicalLights() order
  EnvironmentMode environment = EnvironmentMode::None;
  Precision precision = Precision::Fp32;
  Quality quality = Quality::High;
  // Features of the loaded material that the scene proved constant at their neutral value
  // and that were folded away (no lobe emitted), in the model's feature order.
  std::vector<std::string> folded;
  // Stable, readable and file-name safe:
  //   "<material>.<model>.<lights>.<env>.<precision>[.<quality>][.without-<feature>]..."
  // lights joined by '+' ("dir+point+sphere"); the quality only when it is not "high" and one
  // ".without-<feature>" per folded feature, so that keys of earlier axes never change.
  std::string key() const;
  std::string lightsKey() const;
  bool hasLight(LightType type) const;
  // A light of the permutation reads the LTC table (lightReadsLtcTable).
  bool readsLtcTable() const;
  // ...and its material has a sheen, whose lobe reads the sheen's LTC table too.
  bool readsSheenLtcTable() const;
};

// `light` reads the LTC table when `material` shades it: a rectangle or disk, or a light the
// material's (quality-specialized) light methods shade by kLtcLightMethod.
bool lightReadsLtcTable(const MaterialDesc& material, LightType light);

// The permutations a list of materials needs by default: a directional light, no
// environment, fp32 (what eval, stress and bench run), in input order.
std::vector<Permutation> permutationsFor(const std::vector<MaterialDesc>& materials);

// What `validate` runs for one material: every light type its model shades together, once
// per environment mode the model supports.
std::vector<Permutation> validationPermutationsFor(const MaterialDesc& material, const ShaderLibrary& lib);

}  // namespace mb
