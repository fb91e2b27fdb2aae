// Emit: GLSL 450 text for a brick probe or a material permutation. Only the units and
// bricks reachable from what is emitted are included, each behind a #line directive.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "library/shader_library.hpp"
#include "load/material_desc.hpp"
#include "permute/permutation.hpp"

namespace mb {

// One named input of a probe record. Geometry parameters appear as three Vec3 inputs
// n, v, l: the probe gets vectors and builds the dot products itself.
struct ProbeInput {
  std::string name;
  ValueType type = ValueType::Float;
  uint32_t offset = 0;  // in floats, within a record
};

struct ProbeLayout {
  std::vector<ProbeInput> inputs;
  ValueType output = ValueType::Float;
  uint32_t inStride = 0;   // floats per input record
  uint32_t outStride = 0;  // floats per output record
  // CSV column names: "alpha", "n.x", "n.y", "n.z", ...
  std::vector<std::string> columns() const;
  std::vector<std::string> outputColumns() const;
  const ProbeInput* find(const std::string& name) const;
};

struct EmittedShader {
  std::string key;       // permutation key, or "brick.<id>"
  std::string fileName;  // "<key>.glsl"
  std::string glsl;
  ProbeLayout layout;
  std::vector<std::string> bricks;  // brick ids included, in order
};

// With `unstableVariant`, the probe uses the brick's naive form (Brick::unstableFile).
EmittedShader emitBrickProbe(const ShaderLibrary& lib, const Brick& brick, bool unstableVariant = false);
EmittedShader emitPermutation(const ShaderLibrary& lib, const Permutation& perm);

// Inputs of a material probe: n, v, l, then each non-constant parameter in model order.
ProbeLayout materialProbeLayout(const MaterialDesc& material);

}  // namespace mb
