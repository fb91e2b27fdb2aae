// Emit: GLSL 450 text for a brick probe or a material permutation. Only the units and
// bricks reachable from what is emitted are included, each behind a #line directive.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "library/shader_library.hpp"
#include "emit/precision.hpp"
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
// At ShaderPrecision::Fp16 the brick and its units run in half arithmetic (precision.hpp).
EmittedShader emitBrickProbe(const ShaderLibrary& lib, const Brick& brick, bool unstableVariant = false,
                             ShaderPrecision precision = ShaderPrecision::Fp32);
// The precision comes from the permutation's own axis (Permutation::precision, in its key).
// With `illuminanceInput` the probe reads the light's illuminance (vec3 "illuminance", after
// n, v, l) instead of passing 1, so that stress can drive very large and very small light
// intensities; evaluateMaterial itself is the same either way.
EmittedShader emitPermutation(const ShaderLibrary& lib, const Permutation& perm, bool illuminanceInput = false);
// Permutation::precision as an enum; throws DiagnosticError for an unknown name.
ShaderPrecision precisionOf(const Permutation& perm);
// The brick bound to `slot` in this permutation (the material's choice, adjusted for the
// precision by brickForPrecision).
std::string boundBrick(const Permutation& perm, const std::string& slot);

// Inputs of a material probe: n, v, l, [illuminance,] then each non-constant parameter in
// model order.
ProbeLayout materialProbeLayout(const MaterialDesc& material, bool illuminanceInput = false);

}  // namespace mb
