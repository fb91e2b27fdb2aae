// permute: the permutations a scene requires, derived from the scene (never by enumerating
// the full product and stripping it), with the counts `compile --explain` prints.
#pragma once
#include <deque>
#include <string>
#include <vector>

#include "library/shader_library.hpp"
#include "load/scene_desc.hpp"
#include "permute/axes.hpp"
#include "permute/permutation.hpp"

namespace mb {

// Per material of the scene: what was folded and why the rest was not.
struct MaterialPlanNote {
  std::string material;
  std::vector<std::string> folded;  // features folded away
  std::vector<std::string> absent;  // model features the material never enabled (nothing to fold)
  std::vector<std::pair<std::string, std::string>> keptReasons;  // feature -> why it stays
  // "<level>:<role>" -> the brick that quality level bound instead of the default, and
  // "<level>:<light> lights" -> the light method it chose instead of the default
  std::vector<std::pair<std::string, std::string>> qualityBricks;
};

struct ScenePlan {
  // Owns the specialized materials the permutations point at (stable addresses).
  std::deque<MaterialDesc> specialized;
  std::vector<Permutation> required;   // sorted by key, no duplicates
  size_t possible = 0;                 // sum over the scene's materials of validCombinationCount(model)
  std::vector<AxisSize> possibleAxes;  // of the largest model, for "which axis multiplied"
  // Axes of the scene with more than one value, and their counts (e.g. precision x2).
  std::vector<AxisSize> requiredAxes;
  std::vector<MaterialPlanNote> notes;
};

// Throws DiagnosticError (E-PERMUTATION-INVALID naming the scene file and the light or
// environment the material's model cannot shade) when a required combination is invalid.
ScenePlan planScene(const SceneDesc& scene, const ShaderLibrary& lib);

// The plain `compile MATERIAL...` path as a plan: one permutation per material at the given
// lights, environment, precision and quality of `axes` (its features are ignored: each
// material keeps its own; no folding), so both paths share build and write.
ScenePlan planMaterials(const std::vector<MaterialDesc>& materials, const AxisPoint& axes, const ShaderLibrary& lib);

// `--explain`: the possible, required, compiled and unique (by SPIR-V hash) counts, the axis
// that multiplied each, and per material what was folded (docs/scenes.md shows an example).
// `compiledHow` annotates the compiled count (how many came from the cache).
std::string explainText(const ScenePlan& plan, size_t compiled, size_t uniqueSpirv,
                        const std::string& compiledHow = "");

// A package's permutation keys against the plan's: "" when every required key is present,
// else a unified-diff-like listing ("- key" required but missing, "+ key" present but not
// required) used by `matbricks verify` (a missing permutation is an error, never a fallback).
std::string diffKeys(const std::vector<std::string>& required, const std::vector<std::string>& present);

}  // namespace mb
