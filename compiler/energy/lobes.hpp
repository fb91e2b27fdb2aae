// The lobes the energy checks integrate: products of bricks (D x V for a specular or sheen
// lobe, one brick for a diffuse lobe), built from the library's data. Which D pairs with
// which V is a modelling decision (a GGX V with a Charlie D means nothing), so each D brick's
// manifest "energy" entry names its lobe ("specular", "sheen", "anisotropic") and its V bricks
// ("all" of its lobe, or a list), and each V brick names its lobe: a new V brick of the
// specular lobe is integrated with GGX D, and a new D brick joins the checks, with no code
// change (docs/architecture.md "Adding a brick").
#pragma once
#include <string>
#include <vector>

#include "energy/half_vector_map.hpp"
#include "library/shader_library.hpp"

namespace mb::energy {

enum class LobeKind { Specular, Sheen, Anisotropic, Diffuse };
const char* lobeKindName(LobeKind kind);

// What theory says about the lobe's albedo (the check only fails on Conserving lobes).
enum class Expectation {
  Conserving,     // albedo <= 1 by construction (cited in `note`)
  NotConserving,  // known to exceed 1 somewhere (cited in `note`)
  Unbounded,      // an approximation or empirical form: nothing guarantees <= 1
};
const char* expectationName(Expectation e);

struct Lobe {
  std::string name;  // "d_ggx * v_smith_ggx_correlated"
  LobeKind kind = LobeKind::Specular;
  std::vector<const Brick*> factors;                  // multiplied together: {D, V} or {diffuse}
  HalfVectorMapKind map = HalfVectorMapKind::Cosine;  // quadrature map, from the D brick
  Expectation expectation = Expectation::Unbounded;
  std::string note;  // why, with the source
  const Brick* distribution() const { return factors.front(); }
  // The brick the quadrature nodes are built for: the D brick, or "diffuse".
  std::string familyKey() const { return kind == LobeKind::Diffuse ? "diffuse" : factors.front()->id; }
};

std::vector<Lobe> energyLobes(const ShaderLibrary& lib);

// The lobe the DFG LUT integrates, which the multiple-scattering compensation is checked on:
// the isotropic specular lobe whose D has the GGX half-vector map (the distribution the LUT
// kernel's sample_ggx draws) and whose V is the brick with kernel role "dfg_visibility"
// (d_ggx * v_smith_ggx_correlated in the shipped library). Null when the library has none.
const Lobe* dfgLobe(const std::vector<Lobe>& lobes, const ShaderLibrary& lib);

}  // namespace mb::energy
