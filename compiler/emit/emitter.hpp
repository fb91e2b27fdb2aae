// Emit: GLSL 450 text for a brick probe or a material permutation. Only the units and
// bricks reachable from what is emitted are included, each behind a #line directive.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "library/shader_library.hpp"
#include "emit/precision.hpp"
#include "emit/probe_scene.hpp"
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
  // Outputs after the result that the reference reads back (ProbeRun): with user surface
  // code, the MaterialInputs members surface() computed, so the reference composition is
  // evaluated at exactly the inputs the GPU shaded (there is no C++ form of user GLSL).
  std::vector<ProbeInput> fedOutputs;  // offsets within the output record
  uint32_t fedCount() const;
  // CSV column names: "alpha", "n.x", "n.y", "n.z", ...
  std::vector<std::string> columns() const;
  std::vector<std::string> outputColumns() const;
  const ProbeInput* find(const std::string& name) const;
};

// What a permutation's compute entry point is for (docs/package.md "Kernel ABI"):
//  Probe   validation, stress, bench: every non-constant material parameter is a record input,
//          sampled per record.
//  Engine  the package's kernel: the non-constant material parameters come from one std140
//          uniform block (set 0, binding 2; the C++ header's parameter struct mirrors it) and
//          the records hold only the geometry and the scene's light and environment inputs.
enum class EmitMode { Probe, Engine };

struct EmittedShader {
  std::string key;       // permutation key, or "brick.<id>"
  std::string fileName;  // "<key>.glsl"
  std::string glsl;
  ProbeLayout layout;
  std::vector<std::string> bricks;  // brick ids included, in order
  // The kernel reads the LTC table from the harness's table buffer (a validation probe of a
  // permutation with rectangle or disk lights; ltc::tableTexels is what to give it).
  bool readsTable = false;
};

// With `unstableVariant`, the probe uses the brick's naive form (Brick::unstableFile).
// At ShaderPrecision::Fp16 the brick and its units run in half arithmetic (precision.hpp).
EmittedShader emitBrickProbe(const ShaderLibrary& lib, const Brick& brick, bool unstableVariant = false,
                             ShaderPrecision precision = ShaderPrecision::Fp32);
// The precision comes from the permutation's own axis (Permutation::precision, in its key).
// The probe builds the frame, one light of each type in the permutation and its environment
// from the record (probe_scene.hpp) and sums their radiance. With `illuminanceInput` the
// directional light's illuminance is a record input (vec3 "illuminance", after n, v, l)
// instead of 1, so that stress can drive very large and very small light intensities.
// Throws DiagnosticError (E-PERMUTATION-INVALID) for lights or an environment the model
// does not shade.
// With `mediump`, an fp16 permutation is written as ShaderPrecision::Fp16Mediump (precision.hpp)
// for targets without 16-bit types; an fp32 one is unchanged.
EmittedShader emitPermutation(const ShaderLibrary& lib, const Permutation& perm, bool illuminanceInput = false,
                              EmitMode mode = EmitMode::Probe, bool mediump = false);
// The function of a permutation's probe that evaluates it whole (frame, lights, environment),
// vec3 mbPermutationRadiance(p_<input>...) over the layout's inputs then the engine params: its
// call on the locals p_<input>, which the validation probe's main and the bench kernel make.
std::string permutationRadianceCall(const ProbeLayout& layout, const std::vector<ProbeInput>& params = {});

// What Permutation::precision emits (emit/precision.hpp shaderPrecision).
ShaderPrecision precisionOf(const Permutation& perm);
// The brick bound to `role` in this permutation (the material's choice, adjusted for the
// precision by brickForPrecision).
std::string boundBrick(const ShaderLibrary& lib, const Permutation& perm, const std::string& role);
// role -> brick id of every role the permutation's shader calls, in the model's order.
std::vector<std::pair<std::string, std::string>> boundRoles(const ShaderLibrary& lib, const Permutation& perm);

// The probe scene of a permutation (which record inputs describe frame, lights, environment).
ProbeScene probeSceneOf(const Permutation& perm, bool illuminanceInput = false, EmitMode mode = EmitMode::Probe);
// Inputs of a material probe: n, v, l, the scene's inputs, then each non-constant parameter
// in the material's order.
ProbeLayout materialProbeLayout(const Permutation& perm, bool illuminanceInput = false,
                                EmitMode mode = EmitMode::Probe);

}  // namespace mb
