// Permutation axes and the one place that says which combinations are valid
// (docs/scenes.md "Axes and validity"). Emit, the scene planner and the `--explain` counts
// all ask invalidReason(); nothing else encodes a rule about which axes go together.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/vocabulary.hpp"  // the axes' values: EnvironmentMode, LightType, Precision, Quality
#include "library/shader_library.hpp"
#include "permute/permutation.hpp"

namespace mb {

// One point of the axis space of one model, before it is bound to a material.
struct AxisPoint {
  std::vector<std::string> features;  // enabled, model order
  std::vector<LightType> lights;      // canonicalLights() order; may be empty
  EnvironmentMode environment = EnvironmentMode::None;
  Precision precision = Precision::Fp32;
  Quality quality = Quality::High;
};

// Why this combination is invalid for `model`, or nullopt when it is valid. The rules (each
// with its reason): a light type / environment mode / feature the model does not have, an
// a quality level the model's manifest does not define.
std::optional<std::string> invalidReason(const ShadingModel& model, const AxisPoint& point);
// The same for a bound permutation (its material's features, its lights, ...), and then the
// model's brick rules (brokenBrickRule).
std::optional<std::string> invalidReason(const ShadingModel& model, const Permutation& perm);

// Whether a model role exists in this permutation (its feature, lights, environment).
bool roleActive(const ModelRole& role, const Permutation& perm);

// The first of the model's "incompatible" brick rules that the permutation's bindings break
// (every role of the rule active and bound to the rule's brick), with its message. The rules
// depend on the material's bindings, not on the axes alone, so they are judged per bound
// permutation (after the quality level's bricks) and do not enter validCombinationCount.
struct BrokenBrickRule {
  const BrickRule* rule = nullptr;
  std::string message;
};
std::optional<BrokenBrickRule> brokenBrickRule(const ShadingModel& model, const Permutation& perm);
// Where to report an invalid permutation: for a broken brick rule, where the material chose
// the first of the rule's bricks it chose itself; else where it named its model; else the
// material file.
SourceLocation invalidLocation(const ShadingModel& model, const Permutation& perm);

// The size of each axis of a model's full product, as a keyword system would enumerate it:
// features 2^k, lights 2^n light subsets, environments, precisions, qualities.
struct AxisSize {
  std::string axis;  // "features", "lights", "environment", "precision", "quality"
  size_t values = 1;
};
std::vector<AxisSize> axisSizes(const ShadingModel& model);
// How many points of that product are valid (invalidReason() == nullopt), counted without
// building permutations.
size_t validCombinationCount(const ShadingModel& model);

}  // namespace mb
